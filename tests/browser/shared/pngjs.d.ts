// The part of pngjs (which ships no types) that the browser tests use: decoding a PNG file, and
// encoding one (pictures a test saves beside its results to be looked at).
declare module 'pngjs' {
  interface Image {
    width: number;
    height: number;
    data: Buffer;
  }
  export const PNG: {
    new (options: { width: number; height: number }): Image;
    sync: { read(buffer: Buffer): Image; write(image: Image): Buffer };
  };
}
