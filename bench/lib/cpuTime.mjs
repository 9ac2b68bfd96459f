// The CPU time Chromium spends, for rows timed on a shared machine: under SwiftShader the GPU's
// work is CPU work in Chromium's processes, and their CPU time counts what a frame costs whatever
// else the machine runs, where its wall time grows with the machine's load (the island's 'scene'
// over 'sky' frame at high, six runs of 5 to 9 frames at load 18 to 31: wall-time ratios 1.57 to
// 2.52, CPU-time ratios 1.72 to 1.95; on the quiet machine the wall-time ratio was 1.72).
import { readdirSync, readFileSync } from 'node:fs';

/** The ids of this Node process's descendants (Chromium's processes, Vite's helpers), from /proc. */
function descendants() {
  const parentOf = new Map();
  for (const entry of readdirSync('/proc')) {
    if (!/^\d+$/.test(entry)) continue;
    try {
      const stat = readFileSync(`/proc/${entry}/stat`, 'utf8');
      // After "pid (comm) state": the parent's id (comm may hold spaces and parentheses).
      parentOf.set(Number(entry), Number(stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1]));
    } catch {
      // The process ended while the list was read.
    }
  }
  const family = new Set([process.pid]);
  for (let grew = true; grew; ) {
    grew = false;
    for (const [pid, parent] of parentOf) {
      if (!family.has(pid) && family.has(parent)) {
        family.add(pid);
        grew = true;
      }
    }
  }
  family.delete(process.pid);
  return family;
}

/**
 * The CPU time all threads of this process's descendants have run, ms (Linux's per-thread
 * schedstat, in ns); null where /proc does not give it.
 */
export function descendantsCpuMs() {
  try {
    let ns = 0;
    for (const pid of descendants()) {
      let threads;
      try {
        threads = readdirSync(`/proc/${pid}/task`);
      } catch {
        continue; // ended meanwhile
      }
      for (const thread of threads) {
        try {
          ns += Number(readFileSync(`/proc/${pid}/task/${thread}/schedstat`, 'utf8').split(' ')[0]);
        } catch {
          // The thread ended while the list was read.
        }
      }
    }
    return ns / 1e6;
  } catch {
    return null;
  }
}
