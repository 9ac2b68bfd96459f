import type { Page } from '@playwright/test';

/**
 * Makes the page's WebGL2 contexts report less than they have, as a weaker device would: a smaller
 * MAX_DRAW_BUFFERS (WebGL2 guarantees 4), extensions that are missing, or framebuffers with more
 * than one colour attachment reported incomplete (a driver that cannot render to that combination:
 * FRAMEBUFFER_UNSUPPORTED). The context itself is the real one; only what it reports is changed.
 * `rendererMethods` takes methods out of every WebGLRenderer the page makes, as a three.js release
 * without those internals would have them (three.js assigns them in the constructor: a setter on
 * Object.prototype swallows the assignment).
 */
export async function withHiddenCapabilities(
  page: Page,
  hidden: { maxDrawBuffers?: number; extensions?: readonly string[]; layeredFramebuffers?: false; rendererMethods?: readonly string[] },
): Promise<void> {
  await page.addInitScript((hidden) => {
    const prototype = WebGL2RenderingContext.prototype;
    const getParameter = prototype.getParameter;
    const getExtension = prototype.getExtension;
    const getSupportedExtensions = prototype.getSupportedExtensions;
    const missing = new Set(hidden.extensions ?? []);
    prototype.getParameter = function (this: WebGL2RenderingContext, name: number) {
      if (name === this.MAX_DRAW_BUFFERS && hidden.maxDrawBuffers !== undefined) return hidden.maxDrawBuffers;
      return getParameter.call(this, name);
    };
    prototype.getExtension = function (this: WebGL2RenderingContext, name: string) {
      return missing.has(name) ? null : (getExtension as (this: WebGL2RenderingContext, name: string) => unknown).call(this, name);
    } as typeof getExtension;
    prototype.getSupportedExtensions = function (this: WebGL2RenderingContext) {
      return (getSupportedExtensions.call(this) ?? []).filter((name) => !missing.has(name));
    };
    if (hidden.layeredFramebuffers === false) {
      const checkFramebufferStatus = prototype.checkFramebufferStatus;
      prototype.checkFramebufferStatus = function (this: WebGL2RenderingContext, target: number) {
        const second = this.getFramebufferAttachmentParameter(target, this.COLOR_ATTACHMENT1, this.FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
        return second !== this.NONE ? this.FRAMEBUFFER_UNSUPPORTED : checkFramebufferStatus.call(this, target);
      };
    }
    for (const method of hidden.rendererMethods ?? []) {
      Object.defineProperty(Object.prototype, method, { get: () => undefined, set: () => {}, configurable: true });
    }
  }, hidden);
}
