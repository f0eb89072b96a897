"""Lubricant films: closed-form film formulas, 1-D and 2-D EHL (line, finite line, point), starvation,
the shared nested Newton–Krylov engine (`nested_krylov`) and viscosity against temperature."""
