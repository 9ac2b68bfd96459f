// Where the GPU FFT keeps its data (see src/fft/gpuWaveFields.ts for the whole pipeline).
//
// Every pass of the FFT computes one radix-4 butterfly per fragment: four inputs in, four outputs
// out. A fragment can only write to its own texel, so the four outputs go to the same texel of
// four layers of a 2D array texture (one colour attachment per layer). Compared with the gather
// form (one output per fragment, every output reading all four inputs), each input is read once
// instead of four times: under SwiftShader a pass costs about a third.
//
// Addresses below are (position, line, layer): one line of N complex numbers being transformed
// (a row of constant z for the x axis, a column of constant x for the z axis) is spread over
// N/4 positions of four layers. All working textures are (N/2)×(N/2) arrays of four layers; a
// pass along x stores position p of line l at texel (p + (l mod 2)·N/4, l div 2) (two lines per
// texel row), a pass along z (ALONG_Z) at texel (l mod N/2, p + (l div N/2)·N/4) (lines side by
// side). Either way neighbouring fragments read neighbouring texels, which matters on a CPU:
// reading a texture across its rows made the passes that did it two to three times slower under
// SwiftShader; and both axes share the same two sets of textures.
//
// INPUT_LAYOUT (defined with the shader) says which pass wrote the data being read:
//   QUARTERS             element e at position e mod N/4, layer e div N/4: what the evolution
//                        pass writes, and what the last pass of an axis leaves (natural order)
//   QUARTERS_TRANSPOSED  the first z pass reads the x axis's result, where element z of line x is
//                        element x of line z, stored as the x axis stores: position x mod N/4
//                        of line z, layer x div N/4; as an address here, position z and "line"
//                        x mod N/4, swapped back when it becomes a texel
//   AFTER_RADIX2         written by a radix-2 pass: e = 2i + t, i = b + h·N/4 (h = 0, 1), at
//                        position b, layer 2h + t
//   AFTER_RADIX4         written by a radix-4 pass of sub-length q = p/4: e = g·4q + t·q + r
//                        (r < q) at position g·q + r, layer t
// A pass reads elements b + s·N/4 (s = 0 … 3) of its line, b < N/4. In each layout, element
// b + s·N/4 sits at base + (s mod 2)·stepQuarter + (s div 2)·stepHalf, with the base of element b
// and the two steps below; constant s folds them at compile time.
#define QUARTERS 0
#define QUARTERS_TRANSPOSED 1
#define AFTER_RADIX2 2
#define AFTER_RADIX4 3

struct QuarterAddresses {
  ivec3 base;         // (position, line, layer) of element b
  ivec3 stepQuarter;  // from element e to element e + N/4
  ivec3 stepHalf;     // from element e to element e + N/2
};

// sizeLog2 = log2 N; subtransformLog2 = log2 of the reading pass's sub-transform length p.
QuarterAddresses quarterAddresses(int b, int line, int sizeLog2, int subtransformLog2) {
#if INPUT_LAYOUT == QUARTERS
  return QuarterAddresses(ivec3(b, line, 0), ivec3(0, 0, 1), ivec3(0, 0, 2));
#elif INPUT_LAYOUT == QUARTERS_TRANSPOSED
  int quarterLog2 = sizeLog2 - 2;
  int quarter = 1 << quarterLog2;
  return QuarterAddresses(ivec3(b, line & (quarter - 1), line >> quarterLog2), ivec3(quarter, 0, 0),
                          ivec3(2 * quarter, 0, 0));
#elif INPUT_LAYOUT == AFTER_RADIX2
  return QuarterAddresses(ivec3(b >> 1, line, b & 1), ivec3(1 << (sizeLog2 - 3), 0, 0), ivec3(0, 0, 2));
#else
  // Here P = 4q ≤ N/4 divides N/4: adding N/4 keeps r and t and adds N/(4·4q) to g, that is
  // N/16 to the texel.
  int qLog2 = subtransformLog2 - 2;
  int texel = ((b >> (qLog2 + 2)) << qLog2) | (b & ((1 << qLog2) - 1));
  return QuarterAddresses(ivec3(texel, line, (b >> qLog2) & 3), ivec3(1 << (sizeLog2 - 4), 0, 0),
                          ivec3(1 << (sizeLog2 - 3), 0, 0));
#endif
}

// Texel of position p of line l, as a pass along x stores it.
ivec2 texelAlongX(int p, int l, int sizeLog2) {
  return ivec2(p + ((l & 1) << (sizeLog2 - 2)), l >> 1);
}

// Texel of position p of line l, as a pass along z stores it.
ivec2 texelAlongZ(int p, int l, int sizeLog2) {
  return ivec2(l & ((1 << (sizeLog2 - 1)) - 1), p + ((l >> (sizeLog2 - 1)) << (sizeLog2 - 2)));
}

// (texel x, texel y, layer) of element b + s·N/4 in the arrays being read.
ivec3 quarterAddress(QuarterAddresses addresses, int s, int sizeLog2) {
  ivec3 address = addresses.base + (s & 1) * addresses.stepQuarter + (s >> 1) * addresses.stepHalf;
#if ALONG_Z && INPUT_LAYOUT == QUARTERS_TRANSPOSED
  return ivec3(texelAlongX(address.y, address.x, sizeLog2), address.z);
#elif ALONG_Z
  return ivec3(texelAlongZ(address.x, address.y, sizeLog2), address.z);
#else
  return ivec3(texelAlongX(address.x, address.y, sizeLog2), address.z);
#endif
}

// (texel x, texel y, layer) of field texel (x, z) in a transform's result: the z axis ends in
// QUARTERS with x as the line, element z at position z mod N/4 of layer z div N/4.
ivec3 fieldAddress(ivec2 texel, int sizeLog2) {
  int quarterLog2 = sizeLog2 - 2;
  return ivec3(texelAlongZ(texel.y & ((1 << quarterLog2) - 1), texel.x, sizeLog2), texel.y >> quarterLog2);
}

// (butterfly b, line) of this fragment, which writes texel (b, line) of the next layout (above).
ivec2 fragmentButterfly(int sizeLog2) {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int quarterLog2 = sizeLog2 - 2;
#if ALONG_Z
  return ivec2(texel.y & ((1 << quarterLog2) - 1), texel.x + ((texel.y >> quarterLog2) << (sizeLog2 - 1)));
#else
  return ivec2(texel.x & ((1 << quarterLog2) - 1), (texel.y << 1) + (texel.x >> quarterLog2));
#endif
}
