/** Builds the app (vite build into dist/app) unless it is at least as new as every source file. */
export declare function ensureBuiltApp(options?: { log?: (line: string) => void }): void;
