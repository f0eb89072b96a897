"""Ball bearings (deep groove, angular contact): raceway contact, ball kinematics, the quasi-static
equilibrium of ring and balls, and the limits a solved state is checked against."""
