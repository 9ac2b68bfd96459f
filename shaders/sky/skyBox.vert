// A box around the camera whose fragments look along their world direction: the object-space
// position of a box centred on the origin (SkyEnvironment renders it from the origin).
out vec3 vDirection;

void main() {
  vDirection = position;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
