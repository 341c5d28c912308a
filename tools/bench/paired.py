"""Two runs of ``pybullet_tasks.py`` over the same episodes, side by side.

Success rates of two commits measured on different seeds differ by the seeds as much as by the
code; on the same (task, seed, injection) episodes the comparison is paired: only the episodes
the two runs decided differently say which is better. For each injection mode this prints the
episodes both runs hold, each run's success and claims the world denied, the episodes only one
of them won, the difference with Newcombe's 95 % interval for paired rates and the exact
McNemar p-value, then per task the successes of each::

    python tools/bench/paired.py docs/figures/pybullet_tasks_20_90d2de3.json \\
                                 docs/figures/pybullet_tasks_0ab9ec6.json [--seeds 0-9]
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from tools.bench.intervals import mcnemar_p, paired_difference  # noqa: E402

Key = tuple[str, int, bool]


def episodes(path: str, seeds: range | None) -> dict[Key, dict]:
    rows = json.loads(Path(path).read_text())["episodes"]
    return {(r["task"], r["seed"], r["injection"]): r for r in rows if seeds is None or r["seed"] in seeds}


def won(r: dict) -> bool:
    """Success as the benches count it: claimed, and the world agrees."""
    return bool(r["claimed"] and r["world_success"])


def compare(first: dict[Key, dict], second: dict[Key, dict], injection: bool) -> list[str]:
    keys = sorted(k for k in first.keys() & second.keys() if k[2] == injection)
    if not keys:
        return []
    pairs = [(won(first[k]), won(second[k])) for k in keys]
    both = sum(a and b for a, b in pairs)
    only_first, only_second = sum(a and not b for a, b in pairs), sum(b and not a for a, b in pairs)
    d, lo, hi = paired_difference(both, only_first, only_second, len(pairs) - both - only_first - only_second)
    denied = [sum(r[k]["claimed"] and not r[k]["world_success"] for k in keys) for r in (first, second)]
    mode = "on" if injection else "off"
    out = [f"injection {mode}: {len(keys)} episodes in both runs",
           f"  success   first {both + only_first} ({(both + only_first) / len(keys):.0%})   "
           f"second {both + only_second} ({(both + only_second) / len(keys):.0%})",
           f"  claimed successes the world denies: first {denied[0]}, second {denied[1]}",
           f"  won by the first only {only_first}, by the second only {only_second}: difference {d:+.1%} "
           f"(95 % interval {lo:+.1%} to {hi:+.1%}), exact McNemar p = {mcnemar_p(only_first, only_second):.3f}"]
    for task in sorted({k[0] for k in keys}):
        tk = [k for k in keys if k[0] == task]
        out.append(f"    {task:18s} {sum(won(first[k]) for k in tk):3d} -> {sum(won(second[k]) for k in tk):3d} of {len(tk)}")
    return out


def seed_range(text: str) -> range:
    lo, _, hi = text.partition("-")
    return range(int(lo), int(hi or lo) + 1)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("first", help="JSON of the earlier run (pybullet_tasks.py --json)")
    ap.add_argument("second", help="JSON of the later run")
    ap.add_argument("--seeds", type=seed_range, help="only these seeds, e.g. 0-9")
    args = ap.parse_args(argv)
    first, second = episodes(args.first, args.seeds), episodes(args.second, args.seeds)
    lines = [*compare(first, second, False), *compare(first, second, True)]
    if not lines:
        print("the two runs share no episode", file=sys.stderr)
        return 1
    print(f"first:  {args.first}\nsecond: {args.second}")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
