// The part of pngjs (which ships no types) that the browser tests use: decoding a PNG file.
declare module 'pngjs' {
  export const PNG: {
    sync: { read(buffer: Buffer): { width: number; height: number; data: Buffer } };
  };
}
