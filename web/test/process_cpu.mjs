// CPU time (user + system) of a process and all its descendants, from /proc (Linux): what a
// page costs the machine, which the shared machine's load does not change much, unlike the
// wall time.
import { readdirSync, readFileSync } from "node:fs";

const TICKS_PER_S = 100; // USER_HZ on Linux

function stat(pid) {
  try {
    const text = readFileSync(`/proc/${pid}/stat`, "utf8");
    // Fields after the command name (which may hold spaces) in parentheses.
    const f = text.slice(text.lastIndexOf(")") + 2).split(" ");
    return { ppid: Number(f[1]), ticks: Number(f[11]) + Number(f[12]) };
  } catch {
    return null;
  }
}

//! Seconds of CPU used so far by `root` and every living descendant, with each process's share.
export function treeCpu(root) {
  const all = new Map();
  for (const name of readdirSync("/proc")) {
    if (!/^\d+$/.test(name)) continue;
    const s = stat(name);
    if (s) all.set(Number(name), s);
  }
  const per = new Map();
  const inTree = (pid) => {
    for (let p = pid, hops = 0; p > 1 && hops < 64; p = all.get(p)?.ppid ?? 0, hops++) if (p === root) return true;
    return false;
  };
  for (const [pid, s] of all) if (inTree(pid)) per.set(pid, s.ticks / TICKS_PER_S);
  return per;
}

//! CPU seconds the tree used between two treeCpu snapshots (processes that ended in between
//! are not counted).
export function cpuBetween(before, after) {
  let total = 0;
  for (const [pid, s] of after) total += s - (before.get(pid) ?? 0);
  return total;
}
