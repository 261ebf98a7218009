#!/usr/bin/env python3
"""A template's seeded variants, computed from the generator's description
alone (docs/grading.md, "Variants"), with no mechdyn code: the proof that a variant
is named by its number on any machine.

    python3 variant.py TEMPLATE.json SEED [COUNT]   # JSON lines: {"variant", "parameters"}
"""

import json
import sys

MASK = (1 << 64) - 1


def splitmix64(state):
    """The next state and output of SplitMix64 (Vigna's splitmix64.c)."""
    state = (state + 0x9E3779B97F4A7C15) & MASK
    z = state
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return state, z ^ (z >> 31)


def round_sig(x, digits):
    return float(f"{x:.{digits - 1}e}") if x != 0 else 0.0


def whole(x):
    return int(x) if x == int(x) and abs(x) < 9e15 else x


def draw(parameter, x):
    """The value a draw x gives for a parameter; None when it keeps its default."""
    choices, lo, hi, step = (parameter.get(k) for k in ("choices", "min", "max", "step"))
    if choices:
        return choices[(x * len(choices)) >> 64]
    if lo is None or hi is None or step is None or step <= 0 or hi < lo:
        return None  # min and max alone only bound what a user may ask
    n = int((hi - lo) / step + 1e-9) + 1
    return whole(round_sig(lo + ((x * n) >> 64) * step, 12))


def variant(template, seed):
    state, drawn = seed, {}
    for name in sorted(template["parameters"], key=lambda n: n.encode("utf-8")):
        state, x = splitmix64(state)
        value = draw(template["parameters"][name], x)
        if value is not None:
            drawn[name] = value
    return drawn


def main():
    with open(sys.argv[1], encoding="utf-8") as f:
        template = json.load(f)
    seed, count = int(sys.argv[2]), int(sys.argv[3]) if len(sys.argv) > 3 else 1
    for v in range(seed, seed + count):
        print(json.dumps({"variant": v, "parameters": variant(template, v)}))


if __name__ == "__main__":
    main()
