/** The panel's "copy link": the page's address (the whole state) onto the clipboard, where it can be. */

/** Copies `url`; whether it was copied (no clipboard, or a page that never settles the promise: false). */
export async function copyToClipboard(url: string): Promise<boolean> {
  try {
    if (!navigator.clipboard) throw new Error('no clipboard');
    // Headless or unfocused pages may never settle the promise: give up after a second.
    await Promise.race([
      navigator.clipboard.writeText(url),
      new Promise((_resolve, reject) => setTimeout(() => reject(new Error('clipboard timeout')), 1000)),
    ]);
    return true;
  } catch {
    return false;
  }
}
