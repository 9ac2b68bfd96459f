export declare function serveDirectory(
  root: string,
  options?: { host?: string; port?: number; headers?: Record<string, string> },
): Promise<{ url: string; close: () => Promise<void> }>;
