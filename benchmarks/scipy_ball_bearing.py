"""The classical way, for comparison: the same quasi-static equations in NumPy/SciPy.

Same physics as diffbearing.bearings.ball.ball_equilibrium (Jones–Harris, exact Hertz constants at each contact
angle, outer-raceway control, centrifugal force and gyroscopic moment), solved the usual way:
`scipy.optimize.root` (MINPACK hybr): first the static problem on the 5 ring unknowns (balls on
the line of groove centres) from a plain guess, then all 5 + 2Z unknowns from there (a cold start on
the full system fails, docs/theory.md, §Numerical notes); the stiffness by central finite
differences of the ring force with the balls re-solved (`root` on the 2Z ball unknowns) at ±h.
Vectorized over balls with NumPy; κ by vectorized Newton with scipy.special.ellipk/ellipe.
"""

import numpy as np
from scipy.optimize import root
from scipy.special import ellipe, ellipk


def ellipticity(difference):
    """κ(F) by Newton on F(κ) (Johnson eq. 4.39) with a numerical derivative, vectorized."""
    kappa = ((1 + difference) / (1 - difference)) ** (2 / np.pi)

    def curvature_difference(k):
        m = 1 - 1 / k**2
        return ((k**2 + 1) * ellipe(m) - 2 * ellipk(m)) / ((k**2 - 1) * ellipe(m))

    for _ in range(8):
        h = 1e-7 * kappa
        slope = (curvature_difference(kappa + h) - curvature_difference(kappa - h)) / (2 * h)
        kappa = kappa - (curvature_difference(kappa) - difference) / slope
    return kappa


def contact_constant(curvature_sum, difference, modulus):
    kappa = ellipticity(difference)
    m = 1 - 1 / kappa**2
    return np.pi * kappa * modulus * np.sqrt(2 * ellipe(m) / curvature_sum / (9 * ellipk(m) ** 3))


class ClassicalBallBearing:
    def __init__(self, dw, dm, z, fi, fo, alpha0, modulus, density, speed, centrifugal=True, gyroscopic=True):
        self.dw, self.dm, self.z, self.fi, self.fo, self.alpha0 = dw, dm, z, fi, fo, alpha0
        self.modulus, self.density, self.speed = modulus, density, speed
        self.centrifugal, self.gyroscopic = centrifugal, gyroscopic
        self.psi = 2 * np.pi * np.arange(z) / z
        self.bd = (fi + fo - 1) * dw
        self.arm = dm / 2 + (fi - 0.5) * dw * np.cos(alpha0)

    def centres(self, d):
        a1 = self.bd * np.sin(self.alpha0) + d[2] + self.arm * (d[3] * np.sin(self.psi) - d[4] * np.cos(self.psi))
        a2 = self.bd * np.cos(self.alpha0) + d[0] * np.cos(self.psi) + d[1] * np.sin(self.psi)
        return a1, a2

    def constants(self, alpha_i, alpha_o):
        gi = self.dw * np.cos(alpha_i) / self.dm
        go = self.dw * np.cos(alpha_o) / self.dm
        ti = 4 - 1 / self.fi + 2 * gi / (1 - gi)
        to = 4 - 1 / self.fo - 2 * go / (1 + go)
        ki = contact_constant(ti / self.dw, (1 / self.fi + 2 * gi / (1 - gi)) / ti, self.modulus)
        ko = contact_constant(to / self.dw, (1 / self.fo - 2 * go / (1 + go)) / to, self.modulus)
        return ki, ko

    def ball_state(self, d, x1, x2):
        a1, a2 = self.centres(d)
        do = np.hypot(x1, x2) - (self.fo - 0.5) * self.dw
        di = np.hypot(a1 - x1, a2 - x2) - (self.fi - 0.5) * self.dw
        ao, ai = np.arctan2(x1, x2), np.arctan2(a1 - x1, a2 - x2)
        ki, ko = self.constants(ai, ao)
        qi, qo = ki * np.maximum(di, 0) ** 1.5, ko * np.maximum(do, 0) ** 1.5
        r = self.dw / self.dm
        beta = np.arctan2(np.sin(ao), np.cos(ao) + r)
        tb = np.tan(beta)
        it = (np.cos(ai) + tb * np.sin(ai)) / (1 - r * np.cos(ai))
        ot = (np.cos(ao) + tb * np.sin(ao)) / (1 + r * np.cos(ao))
        wm = self.speed / (1 + it / ot)
        wr = -self.speed / ((ot + it) * r * np.cos(beta))
        fc = np.pi / 12 * self.density * self.dw**3 * self.dm * wm**2 if self.centrifugal else 0 * wm
        # M_g e_t = dL/dt = ω_m ẑ × J ω_R (cos β ẑ − sin β e_r), positive for β > 0 (ω_R < 0)
        mg = -self.density * np.pi * self.dw**5 / 60 * wr * wm * np.sin(beta) if self.gyroscopic else 0 * wm
        return qi, qo, ai, ao, fc, mg

    def ball_residual(self, d, x1, x2):
        qi, qo, ai, ao, fc, mg = self.ball_state(d, x1, x2)
        # outer-raceway friction −(2 M_g/D_w)(cos α_o, −sin α_o) supplies dL/dt about the ball centre
        g = mg / self.dw
        return (qi * np.sin(ai) - qo * np.sin(ao) - 2 * g * np.cos(ao),
                qi * np.cos(ai) - qo * np.cos(ao) + 2 * g * np.sin(ao) + fc)

    def ring_force(self, d, x1, x2):
        qi, _, ai, _, _, _ = self.ball_state(d, x1, x2)
        ax = qi * np.sin(ai)
        return np.array([np.sum(qi * np.cos(ai) * np.cos(self.psi)), np.sum(qi * np.cos(ai) * np.sin(self.psi)),
                         np.sum(ax), self.arm * np.sum(ax * np.sin(self.psi)), -self.arm * np.sum(ax * np.cos(self.psi))])

    def start(self, d):
        """Static ball centres: on the line of groove centres, K_i δ_i^1.5 = K_o δ_o^1.5."""
        a1, a2 = self.centres(d)
        length = np.hypot(a1, a2)
        angle = np.arctan2(a1, a2)
        ki, ko = self.constants(angle, angle)
        radius = (self.fo - 0.5) * self.dw + (length - self.bd) / (1 + (ko / ki) ** (2 / 3))
        return a1 / length * radius, a2 / length * radius

    def solve(self, load, guess):
        """Full 5 + 2Z system by MINPACK hybr, from a displacement guess [m, rad]."""
        z, scale = self.z, np.array([1e-5] * 3 + [1e-5 / self.arm] * 2)
        weight = np.array([1, 1, 1, 1 / self.arm, 1 / self.arm]) / (np.linalg.norm(load) + 1e3)

        def residual(y):
            d = y[:5] * scale
            x1, x2 = y[5:5 + z] * 1e-3, y[5 + z:] * 1e-3
            g1, g2 = self.ball_residual(d, x1, x2)
            return np.concatenate([(self.ring_force(d, x1, x2) - load) * weight, g1 * 1e-3, g2 * 1e-3])

        static = root(lambda y: (self.ring_force(y * scale, *self.start(y * scale)) - load) * weight,
                      guess / scale, method="hybr", tol=1e-12)
        x1, x2 = self.start(static.x * scale)
        solution = root(residual, np.concatenate([static.x, x1 * 1e3, x2 * 1e3]), method="hybr", tol=1e-12)
        d = solution.x[:5] * scale
        return d, solution.x[5:5 + z] * 1e-3, solution.x[5 + z:] * 1e-3, solution.success

    def solve_balls(self, d, x1, x2):
        z = self.z

        def residual(y):
            g1, g2 = self.ball_residual(d, y[:z] * 1e-3, y[z:] * 1e-3)
            return np.concatenate([g1, g2]) * 1e-3

        solution = root(residual, np.concatenate([x1, x2]) * 1e3, method="hybr", tol=1e-12)
        return solution.x[:z] * 1e-3, solution.x[z:] * 1e-3

    def stiffness(self, d, x1, x2, step=1e-8):
        """K by central differences of the ring force, balls re-solved at each ±h."""
        steps = np.array([step] * 3 + [step / self.arm] * 2)
        columns = []
        for j in range(5):
            e = np.zeros(5)
            e[j] = steps[j]
            plus = self.ring_force(d + e, *self.solve_balls(d + e, x1, x2))
            minus = self.ring_force(d - e, *self.solve_balls(d - e, x1, x2))
            columns.append((plus - minus) / (2 * steps[j]))
        return np.stack(columns, axis=1)
