"""Surface deflection of two elastic half-spaces under a pressure grid: Love's rectangle
coefficients and their discrete convolution by zero-padded FFT (DC-FFT).

Frame: x along rolling, y along the roller axis; a uniform grid of nx × ny cells of size
dx × dy with the pressure constant on each cell. The combined normal deflection of both bodies
at the centre of cell i is u_i = Σ_j C_{i−j} p_j with

    C(X, Y) = 2/(π E') ∫∫_cell dx' dy' / √((X − x')² + (Y − y')²)

(Boussinesq; 2/E' = (1−ν₁²)/E₁ + (1−ν₂²)/E₂). The cell integral has Love's (1929) closed form,
see `love_rectangle`. The convolution is not periodic: DC-FFT (Liu, Wang & Liu, Wear 243, 2000)
embeds the coefficients of the 2nx × 2ny offsets in wrap-around order and zero-pads the
pressure, so the product of FFTs is the exact linear convolution at O(N log N).
"""

import jax.numpy as jnp


def _love_primitive(x, y):
    """F(x, y) = x·asinh(y/|x|) + y·asinh(x/|y|) [m], x, y ≠ 0.

    It is x·ln(y + r) + y·ln(x + r) less terms in x alone or y alone, which cancel in the
    four-corner sum, so ∂²F/∂x∂y = 1/r with r = √(x² + y²).
    """
    return x * jnp.arcsinh(y / jnp.abs(x)) + y * jnp.arcsinh(x / jnp.abs(y))


def love_rectangle(x, y, half_length_x, half_length_y):
    """∫∫ dx'dy' / r over the rectangle |x'| ≤ a, |y'| ≤ b, seen from (x, y) [m].

    Love (1929), Phil. Trans. A 228, eq. for uniform pressure on a rectangle; Johnson, Contact
    Mechanics §3.3. Multiplied by (1−ν²)/(πE) it is the deflection of one half-space under unit
    pressure. Valid where no corner coordinate x ± a, y ± b is exactly 0: true at every cell
    centre of a uniform grid, whose offsets are whole multiples of the cell size.
    """
    a, b = half_length_x, half_length_y
    return (_love_primitive(x + a, y + b) - _love_primitive(x + a, y - b)
            - _love_primitive(x - a, y + b) + _love_primitive(x - a, y - b))


def influence_coefficients(nx: int, ny: int, cell_x, cell_y, effective_modulus):
    """Combined deflection [m/Pa] at cell offset (k, l) per unit pressure on a cell, wrap-around
    ordered on a (2nx, 2ny) grid for DC-FFT (offset −k sits at index 2nx − k; index nx is 0).

    Args: grid counts nx, ny; cell sizes dx, dy [m]; E' [Pa] (`hertz.effective_modulus`).
    """
    kx = jnp.concatenate([jnp.arange(nx + 1), jnp.arange(-nx + 1, 0)]).astype(float)
    ky = jnp.concatenate([jnp.arange(ny + 1), jnp.arange(-ny + 1, 0)]).astype(float)
    x = kx[:, None] * cell_x
    y = ky[None, :] * cell_y
    # Offsets ±(nx) are never needed by an nx-long linear convolution: zero them (DC-FFT).
    coefficients = 2.0 / (jnp.pi * effective_modulus) * love_rectangle(x, y, 0.5 * cell_x, 0.5 * cell_y)
    keep = (jnp.abs(kx)[:, None] < nx) & (jnp.abs(ky)[None, :] < ny)
    return jnp.where(keep, coefficients, 0.0)


def coefficient_spectrum(coefficients):
    """rfft2 of the wrap-around coefficients: computed once per grid, reused by every deflection."""
    return jnp.fft.rfft2(coefficients)


def deflection(spectrum, pressure):
    """Combined deflection u [m] of the nx × ny pressure grid [Pa]: linear (not periodic)
    convolution by zero-padded FFT with the spectrum of `influence_coefficients`."""
    nx, ny = pressure.shape
    padded = jnp.fft.rfft2(pressure, s=(2 * nx, 2 * ny))
    return jnp.fft.irfft2(spectrum * padded, s=(2 * nx, 2 * ny))[:nx, :ny]
