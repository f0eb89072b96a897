"""The classical way, for comparison: the roller-bearing lamina equations in NumPy/SciPy.

Same equations as diffbearing.bearings.roller.roller_equilibrium (its module docstring), written again in NumPy:
ISO/TS 16281 laminae q = c (E'/E'_steel) l^{-1/9} w max(δ, 0)^{10/9} on each contact, a rigid rib
carrying the roller along its axis, the roller free across its axis (u) and in tilt (φ), the gap
P_d/4 + z(y_k) with the crown drop z written here for the circular and Johns–Gohar profiles. Solved
the usual way:

* without centrifugal force the rollers sit midway (closed form), and the ring problem is
  `scipy.optimize.root` (MINPACK hybr, finite-difference Jacobian) on the free components of
  Δ = [δx, δy, δz, θx, θy] (a cylindrical bearing has no δz, an imposed misalignment fixes θx, θy)
  from a plain guess;
* with centrifugal force each ring residual re-solves every roller by `scipy.optimize.fsolve` on its
  two unknowns (u, φ), started from the midway position pushed out onto the cup, and hybr continues
  from the static solution;
* the stiffness is a central finite difference of the ring force, the rollers re-solved at each ±h.

Only the parameters are read from diffbearing's objects (`ClassicalRollerBearing.from_diffbearing`).
"""

import numpy as np
from scipy.optimize import fsolve, root

# ISO/TS 16281:2008: Q = c_L l^{8/9} δ^{10/9} [N, mm] for both contacts of a roller of length l.
ISO_LAMINA_CONSTANT = 35948.0
STEEL_MODULUS = 207e9 / (1.0 - 0.3**2)  # E' [Pa] the ISO constant is for
JOHNS_GOHAR_END_FACTOR = 0.3033
DISPLACEMENT_UNIT = 1e-5  # m: scaled ring unknowns
ROLLER_UNIT = 1e-6  # m: scaled roller unknowns


def crown_drop(kind, y, length, modulus, radius, flat_length=0.0, crown_radius=0.0, design_load=0.0):
    """Profile drop z(y) [m]: straight, circular (flat Lz + arc Rc) or Johns–Gohar (design load Q, radius R)."""
    if kind == "straight":
        return np.zeros_like(y)
    if kind == "circular":
        beyond = np.maximum(np.abs(y) - 0.5 * flat_length, 0.0)
        return crown_radius - np.sqrt(crown_radius**2 - beyond**2)
    if kind == "johns_gohar":
        half = 0.5 * length
        half_width = np.sqrt(8.0 * design_load / length * radius / (np.pi * modulus))  # Hertz line b
        scale = 2.0 * design_load / (np.pi * length * modulus)
        return scale * np.log(1.0 / (1.0 - (1.0 - JOHNS_GOHAR_END_FACTOR * half_width / half) * (y / half) ** 2))
    raise NotImplementedError(kind)


class ClassicalRollerBearing:
    """Cylindrical (cup_angle = 0, half_angle = 0) or tapered roller bearing, SI units throughout."""

    def __init__(self, *, small_diameter, large_diameter, length, half_angle, profile, modulus, poisson, density,
                 rollers, pitch_diameter, clearance, cup_angle, laminae, inner_speed=0.0, outer_speed=0.0,
                 centrifugal=False, cylindrical=False):
        self.l, self.theta, self.z, self.dm = length, half_angle, rollers, pitch_diameter
        self.cylindrical, self.centrifugal = cylindrical, centrifugal
        e_prime = modulus / (1.0 - poisson**2)
        self.psi = 2.0 * np.pi * np.arange(rollers) / rollers
        self.width = length / laminae
        self.y = (np.arange(laminae) + 0.5) * self.width - 0.5 * length
        self.alpha_o, self.alpha_i, self.alpha_m = cup_angle, cup_angle - 2 * half_angle, cup_angle - half_angle
        self.n_o = np.array([np.sin(self.alpha_o), np.cos(self.alpha_o)])
        self.n_i = np.array([np.sin(self.alpha_i), np.cos(self.alpha_i)])
        self.t = np.array([np.cos(self.alpha_m), -np.sin(self.alpha_m)])
        mean = 0.5 * (small_diameter + large_diameter)
        # equivalent radius of the inner contact at mid-length (roller + cone, Meusnier) for Johns–Gohar
        inner_radius = 0.5 * pitch_diameter - 0.5 * mean * np.cos(self.alpha_i)
        curvature = 2.0 * np.cos(half_angle) / mean + np.cos(self.alpha_i) / inner_radius
        self.gap = 0.25 * clearance + crown_drop(profile["kind"], self.y, length, e_prime, 1.0 / curvature,
                                                 **{k: v for k, v in profile.items() if k != "kind"})
        self.k = 2.0 ** (10.0 / 9.0) * ISO_LAMINA_CONSTANT * 1e6 * e_prime / STEEL_MODULUS * length ** (-1.0 / 9.0)
        mass = density * np.pi * length / 12.0 * (small_diameter**2 + small_diameter * large_diameter
                                                  + large_diameter**2)
        gamma = mean * np.cos(self.alpha_m) / pitch_diameter
        cage = 0.5 * ((1 - gamma) * inner_speed + (1 + gamma) * outer_speed)
        self.fc = mass * cage**2 * 0.5 * pitch_diameter if centrifugal else 0.0
        self.roller_scale = self.k * self.width * laminae * ROLLER_UNIT ** (10.0 / 9.0)  # roller load at 1 µm [N]
        self.scale = np.array([DISPLACEMENT_UNIT] * 3 + [DISPLACEMENT_UNIT * 2.0 / pitch_diameter] * 2)
        self.weight = np.array([1.0, 1.0, 1.0, 2.0 / pitch_diameter, 2.0 / pitch_diameter])
        self.roller_calls = self.roller_flags = 0  # fsolve calls, and those MINPACK flagged (report)
        self.roller_residual_max = 0.0  # largest scaled residual of a flagged roller solve

    @classmethod
    def from_diffbearing(cls, bearing, raceways, laminae, inner_speed=0.0, centrifugal=False):
        """Read the parameters (floats) of diffbearing's RollerBearing and RollerRaceways."""
        p = bearing.profile
        profile = {"kind": p.kind}
        if p.kind == "circular":
            profile.update(flat_length=float(p.flat_length), crown_radius=float(p.crown_radius))
        elif p.kind == "johns_gohar":
            profile.update(design_load=float(p.design_load))
        return cls(small_diameter=float(bearing.small_diameter), large_diameter=float(bearing.large_diameter),
                   length=float(bearing.length), half_angle=float(bearing.cone_half_angle), profile=profile,
                   modulus=float(bearing.material.elastic_modulus), poisson=float(bearing.material.poisson_ratio),
                   density=float(bearing.material.density), rollers=bearing.roller_count,
                   pitch_diameter=float(raceways.pitch_diameter), clearance=float(raceways.diametral_clearance),
                   cup_angle=float(raceways.cup_angle), laminae=laminae, inner_speed=inner_speed,
                   centrifugal=centrifugal, cylindrical=bearing.kind == "cylindrical_roller")

    # --- kinematics and laminae ----------------------------------------------------------------------
    def lamina(self, approach):
        return self.k * self.width * np.maximum(approach, 0.0) ** (10.0 / 9.0)

    def motion(self, d):
        """Per roller: in-plane translation T (Z, 2) (axial, radial) and tilt θ_t (Z,)."""
        translation = np.stack([np.full(self.z, d[2]), d[0] * np.cos(self.psi) + d[1] * np.sin(self.psi)], axis=1)
        return translation, d[4] * np.cos(self.psi) - d[3] * np.sin(self.psi)

    def cone_terms(self, d):
        """(T·n_i − θ_t (d_m/2) sin α_i, w_f sin θ, θ_t), each (Z,)."""
        translation, tilt = self.motion(d)
        cone = translation @ self.n_i - tilt * 0.5 * self.dm * np.sin(self.alpha_i)
        rib = translation @ self.t - tilt * 0.5 * self.dm * np.cos(self.alpha_m)
        return cone, rib * np.sin(self.theta), tilt

    def approaches(self, d, u, phi):
        """(δ_i, δ_o) (Z, n) for roller positions u (Z,) [m] and tilts φ (Z,) [rad]."""
        cone, rib, tilt = self.cone_terms(d)
        y = self.y[None, :]
        outer = (rib + u * np.cos(self.theta))[:, None] - phi[:, None] * y - self.gap
        inner = (cone + rib - u * np.cos(self.theta))[:, None] - tilt[:, None] * y + phi[:, None] * y - self.gap
        return inner, outer

    def midway(self, d):
        cone, _, tilt = self.cone_terms(d)
        return 0.5 * cone / np.cos(self.theta), 0.5 * tilt

    # --- rollers ---------------------------------------------------------------------------------------
    def roller_residual(self, state, cone, rib, tilt):
        """One roller's (R_u, R_φ/(l/2)) / roller scale for scaled state (u/1 µm, φ (l/2)/1 µm)."""
        u, phi = state[0] * ROLLER_UNIT, state[1] * ROLLER_UNIT / (0.5 * self.l)
        outer = self.lamina(rib + u * np.cos(self.theta) - phi * self.y - self.gap)
        inner = self.lamina(cone + rib - u * np.cos(self.theta) - tilt * self.y + phi * self.y - self.gap)
        across = np.cos(self.theta) * (inner.sum() - outer.sum()) + self.fc * np.cos(self.alpha_m)
        moment = (outer - inner) @ self.y
        return np.array([across, moment / (0.5 * self.l)]) / self.roller_scale

    def solve_rollers(self, d):
        """Rollers (u, φ) in equilibrium at Δ: midway without centrifugal force, else fsolve per roller,
        started midway and pushed out onto the cup (outer contact carrying about F_c)."""
        u, phi = self.midway(d)
        if not self.centrifugal:
            return u, phi
        cone, rib, tilt = self.cone_terms(d)
        inner, _ = self.approaches(d, u, phi)  # midway: equal to the outer approaches
        uniform = (self.fc * np.cos(self.alpha_m) / np.cos(self.theta) / (self.k * self.l)) ** 0.9
        push = (np.maximum(-inner.max(axis=1), 0.0) + uniform) / np.cos(self.theta)
        for j in range(self.z):
            start = np.array([(u[j] + push[j]) / ROLLER_UNIT, phi[j] * 0.5 * self.l / ROLLER_UNIT])
            x, info, flag, _ = fsolve(self.roller_residual, start, args=(cone[j], rib[j], tilt[j]), xtol=1e-13,
                                      full_output=True)
            u[j], phi[j] = x[0] * ROLLER_UNIT, x[1] * ROLLER_UNIT / (0.5 * self.l)
            self.roller_calls += 1
            if flag != 1:  # MINPACK stopped without meeting xtol (mostly at round-off): note the residual
                self.roller_flags += 1
                self.roller_residual_max = max(self.roller_residual_max, float(np.max(np.abs(info["fvec"]))))
        return u, phi

    def roller_loads(self, d, u, phi):
        """(inner (Z, n), outer (Z, n), rib force Q_f (Z,)) [N]."""
        inner, outer = self.approaches(d, u, phi)
        qi, qo = self.lamina(inner), self.lamina(outer)
        rib = np.sin(self.theta) * (qi.sum(1) + qo.sum(1)) + self.fc * np.sin(self.alpha_m)
        return qi, qo, rib

    def ring_force(self, d, rollers=None):
        """[Fx, Fy, Fz, Mx, My] the rollers resist Δ with (rollers re-solved unless given)."""
        u, phi = self.solve_rollers(d) if rollers is None else rollers
        qi, _, rib = self.roller_loads(d, u, phi)
        total = qi.sum(1)
        axial = total * self.n_i[0] + rib * self.t[0]
        radial = total * self.n_i[1] + rib * self.t[1]
        moment = -total * 0.5 * self.dm * np.sin(self.alpha_i) - qi @ self.y - rib * 0.5 * self.dm * np.cos(self.alpha_m)
        return np.array([np.sum(radial * np.cos(self.psi)), np.sum(radial * np.sin(self.psi)), np.sum(axial),
                         -np.sum(np.sin(self.psi) * moment), np.sum(np.cos(self.psi) * moment)])

    # --- ring problem ----------------------------------------------------------------------------------
    def free(self, misalignment):
        mask = np.ones(5, bool)
        if self.cylindrical:
            mask[2] = False
        if misalignment is not None:
            mask[3:] = False
        return mask

    def solve(self, force, moment, guess, misalignment=None):
        """Δ in equilibrium with [F, M] by hybr from `guess` [m, rad]; returns (Δ, success).
        Centrifugal: the static problem first, then the full one from there."""
        load = np.concatenate([force, moment])
        mask = self.free(misalignment)
        fixed = np.zeros(5) if misalignment is None else np.concatenate([[0.0, 0.0, 0.0], misalignment])
        weight = self.weight / (np.linalg.norm(load * self.weight) + self.z * self.roller_scale * 10.0)

        def displacement(x):
            d = fixed.copy()
            d[mask] = x * self.scale[mask]
            return d

        def residual(x, centrifugal):
            d = displacement(x)
            rollers = self.solve_rollers(d) if centrifugal else self.midway(d)
            return ((self.ring_force(d, rollers) - load) * weight)[mask]

        static = root(residual, guess[mask] / self.scale[mask], args=(False,), method="hybr", tol=1e-13)
        if not self.centrifugal:
            return displacement(static.x), bool(static.success)
        full = root(residual, static.x, args=(True,), method="hybr", tol=1e-13)
        return displacement(full.x), bool(static.success and full.success)

    def stiffness(self, d, step=1e-11):
        """K = dF/dΔ (5×5) by central differences, rollers re-solved at each ±h [m] (h·2/d_m [rad] for
        the tilts); h ≈ ε^{1/3} δ. A lamina whose approach is within h of 0 (where q ∝ δ^{10/9} starts)
        is differenced across its kink, an error of order one lamina's stiffness: on the benchmark's
        cases 1e-3 of the largest entry at h = 1e-8 m, down to ~1e-9 where no lamina is that close."""
        steps = step * np.array([1.0, 1.0, 1.0, 2.0 / self.dm, 2.0 / self.dm])
        columns = []
        for j in range(5):
            e = np.zeros(5)
            e[j] = steps[j]
            columns.append((self.ring_force(d + e) - self.ring_force(d - e)) / (2 * steps[j]))
        return np.stack(columns, axis=1)

    def max_roller_residual(self, d):
        """Largest scaled roller residual |(R_u, R_φ/(l/2))| / (roller load at 1 µm) at Δ, rollers re-solved."""
        u, phi = self.solve_rollers(d)
        cone, rib, tilt = self.cone_terms(d)
        states = np.stack([u / ROLLER_UNIT, phi * 0.5 * self.l / ROLLER_UNIT], axis=1)
        return max(float(np.max(np.abs(self.roller_residual(s, c, r, t)))) for s, c, r, t in zip(states, cone, rib, tilt))

    def results(self, d):
        """(inner roller loads Q_i (Z,), outer Q_o (Z,), rib forces (Z,), roller tilts φ (Z,)) at Δ."""
        u, phi = self.solve_rollers(d)
        qi, qo, rib = self.roller_loads(d, u, phi)
        return qi.sum(1), qo.sum(1), rib, phi
