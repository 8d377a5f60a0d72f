#!/usr/bin/env python3
"""The corpus gate's figures from `signweave-cli check` output (docs/SYNTHESIS.md quotes them).

    tools/check_census.py AFTER.txt [BEFORE.txt]

One check output (JSON lines, one per sign, then a summary): how many signs are deeper than
5 / 20 / 50 mm, the deepest, how many move a wrist or elbow more than 100 / 150 / 300 mm in one
frame, and how many change that step by more than 56 mm between frames. With BEFORE as well,
the signs that changed: deeper or shallower by more than 2 mm, and the largest changes.
"""
import json
import sys


def read(path):
    signs = []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f):
            line = line.strip()
            if not line.startswith("{"):
                continue
            j = json.loads(line)
            if "summary" in j:
                continue
            d = j.get("steps", {}).get("synthesise", {}).get("detail")
            key = (n, j.get("gloss", ""))
            signs.append((key, d))
    return signs


def census(signs):
    ds = [d for _, d in signs if d]
    depth = [d.get("max_penetration_m", 0.0) * 1000 for d in ds]
    step = [d.get("max_arm_step_m", 0.0) * 1000 for d in ds]
    change = [d.get("max_arm_step_change_m", 0.0) * 1000 for d in ds]
    deepest = max(zip(depth, [k[1] for k, d in signs if d]), default=(0, ""))
    return {
        "synthesised": len(ds),
        "over_5_20_50_mm": [sum(x > t for x in depth) for t in (5, 20, 50)],
        "deepest_mm": [round(deepest[0], 1), deepest[1]],
        "steps_over_100_150_300_mm": [sum(x > t for x in step) for t in (100, 150, 300)],
        "step_changes_over_56_mm": sum(x > 56 for x in change),
    }


def main():
    after = read(sys.argv[1])
    print(json.dumps({"after": census(after)}, ensure_ascii=False))
    if len(sys.argv) < 3:
        return
    before = read(sys.argv[2])
    print(json.dumps({"before": census(before)}, ensure_ascii=False))
    if len(before) != len(after):
        print("the two outputs have different sign counts: no per-sign comparison")
        return
    changed, deeper, shallower = [], 0, 0
    for (key, a), (_, b) in zip(after, before):
        if a == b:
            continue
        da = (a or {}).get("max_penetration_m", 0.0) * 1000
        db = (b or {}).get("max_penetration_m", 0.0) * 1000
        sa = (a or {}).get("max_arm_step_m", 0.0) * 1000
        sb = (b or {}).get("max_arm_step_m", 0.0) * 1000
        deeper += da > db + 2
        shallower += da < db - 2
        changed.append((abs(da - db) + abs(sa - sb) / 10, key[1], db, da, sb, sa))
    print(f"changed {len(changed)}, deeper by > 2 mm {deeper}, shallower by > 2 mm {shallower}")
    for _, gloss, db, da, sb, sa in sorted(changed, reverse=True)[:15]:
        print(f"  {gloss}: depth {db:.1f} -> {da:.1f} mm, step {sb:.1f} -> {sa:.1f} mm")


if __name__ == "__main__":
    main()
