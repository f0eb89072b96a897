"""Cage dynamics: the cage centre's planar whirl and its spin, integrated in time.

The cage paper (docs/theory.md, §Cage dynamics and stability; docs/papers.md, §The cage paper;
Liu et al. 2020, §4, the experiment on pocket / guide clearance). The quasi-static model
(`cage_forces`) prescribes which balls push and which resist; here the roles follow from the
motion:

* balls inside the Sjövall load zone (`load_zone_half`) are held by the raceways at the epicyclic
  orbital speed ω_m: their orbital lag λ_j relaxes to ω_m within `traction_time` τ_t (the raceway
  traction, tens of newtons, dwarfs any pocket force); balls outside it are free, slowed by their
  oil drag f_v (`ball_drag`) until a pocket wall carries them. The switch is smooth over
  ±`ZONE_EDGE` at the zone's edges (values and gradients stay continuous as balls orbit through);
* ball j sits on the pitch circle at θ_j = φ_F + 2πj/Z + ω_m t + λ_j, pocket j's centre at
  c + (d_m/2) ê_r(φ_F + 2πj/Z + ω_m t + φ), with c = (x, y) the cage centre and φ the cage's
  phase against the epicyclic rotation; a ball presses the wall by its penetration
  (`pocket_impact_force`, Hunt–Crossley damping, Coulomb friction from the ball's spin);
* the two outer-ring lands carry the squeeze-film force of a whirling short bearing
  (`whirling_land_force`; metal contact below the film threshold) and the shear torque;
* cage: m c̈ = Σ pocket + land forces, I φ̈ = Σ their moments about the axis; ball:
  m_b (d_m/2) λ̈_j = its pocket force's circumferential part − free-ball drag − raceway traction.
  Planar (no tilt, no gravity): 6 + 2Z states.

Integrator: diffrax's Tsit5 with a PID step controller on the scaled state (`state_scale`). The
steps shrink through each pocket impact (tens of microseconds) and the squeeze film near a land,
and open up in free flight. `python benchmarks/cage_whirl_ratio.py`: over 5 ms of the cage
paper's cage at 20000 r/min, Tsit5 takes 0.11 s and Kvaerno5 (an implicit ESDIRK) 20.7 s, with
whirl radii equal to 5 × 10⁻⁶ relative — the stiffness is oscillatory (contacts), which an
implicit scheme must resolve too. A scan of fixed steps would be held to the shortest impact
throughout. Reverse-mode derivatives come from diffrax's checkpointed adjoint, but over many
revolutions the orbit is an impact oscillator whose measures are not differentiable in any useful
sense (`cage_stability` says why and gives the smooth objective).

Stability measures of the orbit c(t) (`orbit_measures`), over the second half of the run:
mean position c̄ and its offset |c̄|; whirl radius, the RMS of |c − c̄|; decay rate of the
whirl amplitude; spectrum of the whirl z = (x − x̄) + i(y − ȳ) (signed frequencies: forward
whirl > 0) and its dominant frequency.
"""

import diffrax
import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ..numerics import safe_norm
from ..params import BallBearing, Cage, Lubricant, Operating
from .cage_forces import ball_drag, epicyclic_cage_speed, load_zone_half
from .cage_lands import whirling_land_force
from .cage_pocket import ball_spin, pocket_impact_force, pocket_stiffness, radial_distance_on_sphere

# Half-width [rad] of the smooth switch between raceway-held and free balls at the load zone's edge.
ZONE_EDGE = np.deg2rad(2.0)
SOLVER = diffrax.Tsit5()


class CageMotion(eqx.Module):
    """State of the cage and its balls (inertial frame, SI)."""

    centre: jax.Array  # (2,) cage centre c [m]
    velocity: jax.Array  # (2,) ċ [m/s]
    phase: jax.Array  # φ, cage angle less ω_m t [rad]
    spin: jax.Array  # φ̇, cage speed less ω_m [rad/s]
    ball_lag: jax.Array  # (Z,) λ_j, ball orbital angle less its epicyclic position [rad]
    ball_lag_rate: jax.Array  # (Z,) λ̇_j [rad/s]


class CageOrbit(eqx.Module):
    """A simulated cage orbit and its stability measures (SI)."""

    t: jax.Array  # (T,) sample times [s]
    centre: jax.Array  # (T, 2) cage centre [m]
    spin: jax.Array  # (T,) cage speed less ω_m [rad/s]
    cage_speed: jax.Array  # ω_m, the epicyclic cage speed [rad/s]
    mean_offset: jax.Array  # |c̄| over the second half [m]
    whirl_radius: jax.Array  # RMS of |c − c̄| over the second half [m]
    decay_rate: jax.Array  # −d ln(amplitude)/dt of the whirl [1/s]; > 0: the whirl dies out
    frequency: jax.Array  # (F,) signed whirl frequencies [Hz] (forward whirl > 0)
    spectrum: jax.Array  # (F,) amplitude of the whirl at each frequency [m]
    whirl_frequency: jax.Array  # the dominant whirl frequency [Hz]
    land_contact: jax.Array  # (T,) metal contact force at one land [N]
    converged: jax.Array  # the integration reached the end time


class DynamicsSettings(eqx.Module):
    """Choices of the dynamic model that a scene does not set (defaults stated in the docs)."""

    pocket_damping: jax.Array = eqx.field(converter=jnp.asarray, default=10.0)  # Hunt–Crossley α [s/m]
    traction_time: jax.Array = eqx.field(converter=jnp.asarray, default=5e-5)  # τ_t of the raceway hold [s]
    rtol: float = eqx.field(static=True, default=1e-5)  # of the scaled state (`state_scale`)
    atol: float = eqx.field(static=True, default=1e-5)
    max_steps: int = eqx.field(static=True, default=200_000)


def cage_mass_properties(cage: Cage, bearing: BallBearing):
    """(mass [kg], polar moment of inertia [kg·m²]) of the cage estimated as a ring of the cage's
    material between radii R_o = (d_land − c_g)/2 and d_m − R_o, of width s + L, less Z
    cylindrical pockets of diameter D_w + c_p (about 3.7 g for the B7005-class scene)."""
    outer = cage.outer_radius
    inner = bearing.pitch_diameter - outer
    width = cage.land_spacing + cage.land_width
    pocket_radius = 0.5 * (bearing.ball_diameter + cage.pocket_clearance)
    ring = jnp.pi * (outer**2 - inner**2) * width
    pockets = bearing.ball_count * jnp.pi * pocket_radius**2 * (outer - inner)
    mass = cage.material.density * (ring - pockets)
    return mass, 0.5 * mass * (outer**2 + inner**2)


def cage_land_force(cage: Cage, operating: Operating, lubricant: Lubricant, position, velocity, cage_speed):
    """`whirling_land_force` of one land for the cage centre at `position` [m] moving at
    `velocity` [m/s], the cage turning at `cage_speed` [rad/s]: (force, torque, ε, N_m)."""
    return whirling_land_force(position, velocity, 0.5 * cage.guide_clearance, cage.land_width, cage.outer_radius,
                               cage_speed, operating.outer_speed, lubricant.viscosity, cage.film_threshold,
                               cage.contact_stiffness, cage.friction)


def cage_vector_field(t, state: CageMotion, args):
    """d(state)/dt of the cage and its balls (module docstring); `args` = (cage, bearing,
    operating, lubricant, settings)."""
    cage, bearing, operating, lubricant, settings = args
    count = bearing.ball_count
    pitch_radius = 0.5 * bearing.pitch_diameter
    ball_radius = 0.5 * bearing.ball_diameter
    pocket_radius = ball_radius + 0.5 * cage.pocket_clearance
    orbital = epicyclic_cage_speed(bearing, operating)
    load_direction = jnp.arctan2(operating.force[1], operating.force[0])
    slots = load_direction + 2.0 * jnp.pi * jnp.arange(count) / count

    def ball_in_pocket(centre, phase, lag, time):
        """(x_b, y_b) of each ball in its pocket's frame [m]."""
        pocket_angle = slots + orbital * time + phase
        ball_angle = slots + orbital * time + lag
        relative = pitch_radius * (jnp.stack([jnp.cos(ball_angle), jnp.sin(ball_angle)], -1)
                                   - jnp.stack([jnp.cos(pocket_angle), jnp.sin(pocket_angle)], -1)) - centre
        return jnp.stack([jnp.sum(relative * jnp.stack([jnp.cos(pocket_angle), jnp.sin(pocket_angle)], -1), -1),
                          jnp.sum(relative * jnp.stack([-jnp.sin(pocket_angle), jnp.cos(pocket_angle)], -1), -1)],
                         -1)

    def approach(centre, phase, lag, time):
        offset = ball_in_pocket(centre, phase, lag, time)
        sphere = radial_distance_on_sphere(offset[:, 0], cage.pocket)
        return safe_norm(jnp.stack([sphere, offset[:, 1]], -1), axis=-1)

    positions = (state.centre, state.phase, state.ball_lag, jnp.asarray(t, float))
    rates = (state.velocity, state.spin, state.ball_lag_rate, jnp.ones(()))
    offsets = ball_in_pocket(*positions)
    _, approach_rate = jax.jvp(approach, positions, rates)

    stiffness = pocket_stiffness(ball_radius, pocket_radius, bearing.ball_material.elastic_modulus,
                                 bearing.ball_material.poisson_ratio, cage.material.elastic_modulus,
                                 cage.material.poisson_ratio, cage.pocket)
    spin = ball_spin(operating.inner_speed - operating.outer_speed, bearing.pitch_diameter, bearing.ball_diameter,
                     bearing.free_contact_angle)
    local_force, contact = jax.vmap(
        lambda offset, rate: pocket_impact_force(offset, rate, pocket_radius, ball_radius, spin, cage.friction,
                                                 stiffness, settings.pocket_damping, cage.pocket))(offsets, approach_rate)
    pocket_angle = slots + orbital * t + state.phase
    radial = jnp.stack([jnp.cos(pocket_angle), jnp.sin(pocket_angle)], -1)
    tangential = jnp.stack([-jnp.sin(pocket_angle), jnp.cos(pocket_angle)], -1)
    pocket_forces = local_force[:, :1] * radial + local_force[:, 1:] * tangential  # on the cage, inertial
    arms = (pitch_radius + contact[:, :1]) * radial + contact[:, 1:] * tangential
    pocket_torque = jnp.sum(arms[:, 0] * pocket_forces[:, 1] - arms[:, 1] * pocket_forces[:, 0])

    land, land_torque, _, _ = cage_land_force(cage, operating, lubricant, state.centre, state.velocity,
                                              orbital + state.spin)

    mass, inertia = cage_mass_properties(cage, bearing)
    acceleration = (jnp.sum(pocket_forces, 0) + 2.0 * land) / mass
    spin_rate = (pocket_torque + 2.0 * land_torque) / inertia

    # balls: the wall force on the ball is the reaction; its circumferential part turns the ball
    ball_angle = slots + orbital * t + state.ball_lag
    ball_tangent = jnp.stack([-jnp.sin(ball_angle), jnp.cos(ball_angle)], -1)
    wall_push = -jnp.sum(pocket_forces * ball_tangent, -1)
    zone = jnp.abs(jnp.angle(jnp.exp(1j * (ball_angle - load_direction))))
    held = jax.nn.sigmoid((load_zone_half(bearing, operating.force) - zone) / (0.5 * ZONE_EDGE))
    ball_mass = bearing.ball_material.density * jnp.pi * bearing.ball_diameter**3 / 6.0
    orbit_speed = pitch_radius * (orbital + state.ball_lag_rate)
    drag = jnp.sign(orbit_speed) * ball_drag(orbit_speed, bearing.ball_diameter, lubricant.density,
                                             lubricant.viscosity)
    lag_acceleration = ((1.0 - held) * (wall_push - drag) / (ball_mass * pitch_radius)
                        - held * state.ball_lag_rate / settings.traction_time)
    return CageMotion(centre=state.velocity, velocity=acceleration, phase=state.spin, spin=spin_rate,
                      ball_lag=state.ball_lag_rate, ball_lag_rate=lag_acceleration)


def simulate_cage(cage: Cage, bearing: BallBearing, operating: Operating, lubricant: Lubricant, start_offset,
                  duration, samples: int = 512, settings: DynamicsSettings | None = None) -> CageOrbit:
    """The cage's orbit from rest at `start_offset` (x, y) [m], balls centred in their pockets,
    over `duration` [s], sampled at `samples` times, with its stability measures (module
    docstring). `converged` is False when the solver stopped early (step limit or failure)."""
    settings = DynamicsSettings() if settings is None else settings
    count = bearing.ball_count
    start = CageMotion(centre=jnp.asarray(start_offset, float), velocity=jnp.zeros(2), phase=jnp.zeros(()),
                       spin=jnp.zeros(()), ball_lag=jnp.zeros(count), ball_lag_rate=jnp.zeros(count))
    scale = state_scale(cage, bearing, operating, count)

    def scaled_field(t, scaled, args):
        rate = cage_vector_field(t, jax.tree.map(jnp.multiply, scaled, scale), args)
        return jax.tree.map(jnp.divide, rate, scale)

    times = jnp.linspace(0.0, duration, samples)
    solution = diffrax.diffeqsolve(
        diffrax.ODETerm(scaled_field), SOLVER, t0=0.0, t1=duration, dt0=1e-6,
        y0=jax.tree.map(jnp.divide, start, scale), args=(cage, bearing, operating, lubricant, settings),
        saveat=diffrax.SaveAt(ts=times), stepsize_controller=diffrax.PIDController(rtol=settings.rtol,
                                                                                  atol=settings.atol),
        max_steps=settings.max_steps, throw=False)
    states = jax.tree.map(jnp.multiply, solution.ys, scale)
    orbital = epicyclic_cage_speed(bearing, operating)
    land_contact = jax.vmap(lambda c, v, w: cage_land_force(cage, operating, lubricant, c, v, w)[3])(
        states.centre, states.velocity, orbital + states.spin)
    measures = orbit_measures(times, states.centre)
    return CageOrbit(t=times, centre=states.centre, spin=states.spin,
                     cage_speed=orbital, land_contact=land_contact,
                     converged=solution.result == diffrax.RESULTS.successful, **measures)


def state_scale(cage: Cage, bearing: BallBearing, operating: Operating, count: int) -> CageMotion:
    """Scale of each state (the integrator's error control sees state / scale): lengths by the
    radial guide clearance C, angles by C/(d_m/2), rates by those over 1/(|ω_m| + 1 rad/s)."""
    length = 0.5 * cage.guide_clearance
    angle = length / (0.5 * bearing.pitch_diameter)
    rate = jnp.abs(epicyclic_cage_speed(bearing, operating)) + 1.0
    ones = jnp.ones(count)
    return CageMotion(centre=length * jnp.ones(2), velocity=length * rate * jnp.ones(2), phase=angle,
                      spin=angle * rate, ball_lag=angle * ones, ball_lag_rate=angle * rate * ones)


def orbit_measures(times, centre) -> dict:
    """Stability measures of an orbit `centre` (T, 2) [m] sampled at uniform `times` (T,) [s]
    (module docstring): mean_offset, whirl_radius, decay_rate, frequency, spectrum,
    whirl_frequency. The decay rate is the least-squares slope of ln A over four windows of the
    run, A the RMS of |c − c̄| in each window (c̄ the mean of the second half)."""
    samples = times.shape[0]
    late = centre[samples // 2:]
    mean = jnp.mean(late, axis=0)
    deviation = late - mean
    whirl_radius = jnp.sqrt(jnp.mean(jnp.sum(deviation**2, -1)))
    windows = (centre[: samples - samples % 4] - mean).reshape(4, -1, 2)
    amplitude = jnp.sqrt(jnp.mean(jnp.sum(windows**2, -1), -1))
    window_time = jnp.mean(times[: samples - samples % 4].reshape(4, -1), -1)
    log_amplitude = jnp.log(jnp.maximum(amplitude, 1e-300))
    centred_time = window_time - jnp.mean(window_time)
    decay_rate = -jnp.sum(centred_time * (log_amplitude - jnp.mean(log_amplitude))) / jnp.sum(centred_time**2)
    whirl = deviation[:, 0] + 1j * deviation[:, 1]
    window = jnp.hanning(whirl.shape[0])
    spectrum = jnp.abs(jnp.fft.fftshift(jnp.fft.fft(whirl * window))) * 2.0 / jnp.sum(window)
    step = times[1] - times[0]
    frequency = jnp.fft.fftshift(jnp.fft.fftfreq(whirl.shape[0], 1.0)) / step
    return {"mean_offset": safe_norm(mean), "whirl_radius": whirl_radius, "decay_rate": decay_rate,
            "frequency": frequency, "spectrum": spectrum, "whirl_frequency": frequency[jnp.argmax(spectrum)]}
