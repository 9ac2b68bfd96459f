export declare function serveDirectory(
  root: string,
  options?: { host?: string; port?: number },
): Promise<{ url: string; close: () => Promise<void> }>;
