"""Heat: the thermal speed ratings of ISO 15312 and DIN 732 (`thermal_speed`), steady thermal networks
(`thermal_network`) and their conductances (`conductance`)."""
