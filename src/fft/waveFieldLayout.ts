/**
 * What the field textures hold. Both simulation paths (GPU and JS) produce exactly this layout,
 * N×N RGBA float texels, texel (column i, row j) at world point (x, z) = (i, j)·patchSize/N,
 * sampled with REPEAT wrapping at uv = (x, z)/patchSize:
 *
 *   displacement = (Dx, h, Dz, ∂Dx/∂z)            metres; (Dx, h, Dz) moves a surface point
 *   derivatives  = (∂h/∂x, ∂h/∂z, ∂Dx/∂x, ∂Dz/∂z)  dimensionless
 *
 * The Jacobian of the choppy map x → x + (Dx, Dz), which goes negative where waves fold (foam),
 * is J = (1 + ∂Dx/∂x)·(1 + ∂Dz/∂z) − (∂Dx/∂z)² (Tessendorf 2001, §4.6); ∂Dz/∂x = ∂Dx/∂z.
 *
 * Spectra of the fields from h̃ = h̃(k, t) (Tessendorf 2001, eqs. 20 and 29), with λ the choppiness:
 *   h:      h̃                       ∂h/∂x:  i·kx·h̃          ∂h/∂z: i·kz·h̃
 *   Dx:     i·λ·kx/k·h̃              Dz:     i·λ·kz/k·h̃
 *   ∂Dx/∂x: −λ·kx²/k·h̃             ∂Dz/∂z: −λ·kz²/k·h̃      ∂Dx/∂z: −λ·kx·kz/k·h̃
 * Sign of D: Tessendorf writes x + λ·D with D = Σ −i·k/k·h̃·e^{ik·x}. For one wave h = cos(k·x)
 * that D is +sin(k·x), which with λ > 0 would stretch crests and sharpen troughs. We store −λ·D
 * so that a positive choppiness sharpens crests, as a Gerstner wave does.
 *
 * Two real fields share one complex inverse FFT: the spectra above are Hermitian, so the
 * transform of F + i·G is f + i·g. The four packed spectra, in texture order, are
 *   Dx + i·h,   Dz + i·∂Dx/∂z,   ∂h/∂x + i·∂h/∂z,   ∂Dx/∂x + i·∂Dz/∂z.
 */
/** The two field textures, in this order in the GPU path's output target. */
export const FIELD_TEXTURES = ['displacement', 'derivatives'] as const;
