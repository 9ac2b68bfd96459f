// The sky behind everything: a unit box around the eye, drawn at the far plane (z = w), so that
// after the sea it only shades pixels nothing else covered (SkyBackground, src/render/skyBackground.ts).
varying vec3 vDirection;

void main() {
  vDirection = position;
  vec4 clip = projectionMatrix * vec4(mat3(viewMatrix) * position, 1.0);  // rotation only: centred on the eye
  gl_Position = clip.xyww;
}
