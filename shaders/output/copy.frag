// Copies the resolved multisampled picture onto the canvas texel for texel: its bytes are already
// tone mapped and sRGB encoded (render/sceneOutput.ts), so they are written as they are.
uniform sampler2D source;

void main() {
  gl_FragColor = texelFetch(source, ivec2(gl_FragCoord.xy), 0);
}
