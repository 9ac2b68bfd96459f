/**
 * How <fft-ocean> looks before and beside its picture: the shadow root's stylesheet (the sizer that
 * gives the box a height, the placeholder background) and the message that replaces the picture
 * when the sea cannot be drawn.
 */

// The background is a sky-and-sea placeholder until the first frame (or without WebGL 2).
// The sizer gives the box a height (16:9 of its width, at least 150 px) when the page sets none;
// a height from the page wins (the box clips the sizer). It adds no minimum width, so the element
// shrinks in grids and flex rows like any block (unlike aspect-ratio, which would also turn a
// page's height into a width).
const STYLE = `
  :host { display: block; position: relative; overflow: hidden;
          background: linear-gradient(#a9c0d3, #e3e8ea 49%, #2a4a66 50%, #0b1620); }
  :host([hidden]) { display: none; }
  .sizer { box-sizing: border-box; padding-top: 56.25%; min-height: 150px; }
  canvas { position: absolute; inset: 0; width: 100%; height: 100%; display: block; }
  .message { position: absolute; inset: 0; display: flex; align-items: center; justify-content: center;
             box-sizing: border-box; padding: 1em; text-align: center; color: #dde6ee;
             font: 15px/1.45 system-ui, sans-serif; background: linear-gradient(#5d86a8, #17324a 55%, #0b1620); }
`;

/** STYLE as a stylesheet, shared by every element of the page; made on first use (only browsers have it). */
let sharedSheet: CSSStyleSheet | null = null;

/**
 * Gives a shadow root STYLE and the sizer. A constructed stylesheet (adoptedStyleSheets) is allowed
 * by a strict Content-Security-Policy (style-src 'self', no 'unsafe-inline'), which blocks a <style>
 * element; browsers without constructable stylesheets (Safari 15 to 16.3, which have WebGL 2) get
 * the <style> element instead.
 */
export function styleShadowRoot(root: ShadowRoot): void {
  if ('adoptedStyleSheets' in root && 'replaceSync' in CSSStyleSheet.prototype) {
    if (!sharedSheet) {
      sharedSheet = new CSSStyleSheet();
      sharedSheet.replaceSync(STYLE);
    }
    root.adoptedStyleSheets = [sharedSheet];
  } else {
    const style = document.createElement('style');
    style.textContent = STYLE;
    root.append(style);
  }
  const sizer = document.createElement('div');
  sizer.className = 'sizer';
  root.append(sizer);
}

/** Shows `text` over the box in place of the picture; returns the message, for removal. */
export function showMessage(root: ShadowRoot, text: string): HTMLElement {
  const message = document.createElement('div');
  message.className = 'message';
  message.setAttribute('part', 'message');
  message.setAttribute('role', 'note');
  message.textContent = text;
  root.append(message);
  return message;
}
