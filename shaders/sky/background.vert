// The sky behind everything: one triangle that covers the screen, at the far plane (z = w = 1, or
// z = 0 under a reversed depth buffer: farDepth),
// so that after the sea it only shades pixels nothing else covered (SkyBackground,
// src/render/skyBackground.ts). Each corner carries the world direction of its view ray; the
// direction is an affine function of the screen position, so interpolating it is exact.
// (A box around the eye drawn with z = w was clipped into garbage by SwiftShader when the view ran
// exactly along one of its edges, e.g. 45° down along ±z: the sky covered the sea.)
uniform mat4 skyProjectionInverse;  // the camera's projectionMatrixInverse
uniform mat3 skyCameraRotation;     // the camera's rotation (its matrixWorld without translation)
uniform float farDepth;             // the far plane's clip-space z
varying vec3 vDirection;

void main() {
  vec4 view = skyProjectionInverse * vec4(position.xy, farDepth, 1.0);
  vDirection = skyCameraRotation * (view.xyz / view.w);
  gl_Position = vec4(position.xy, farDepth, 1.0);
}
