#!/usr/bin/env python3
"""The draw of make test's sampled store check (verify_sample.sh; issue 61, item 6).

Every unit above its file's coarse levels whose predicted time is at most --max-unit seconds
has a known chance per run, p = min(1, tau / c), where c = overhead + slow * (predicted seconds)
is its predicted cost here and tau is set so that the expected cost of a run, sum p c, is the
budget: a cheap unit is drawn often, an expensive one rarely, and every one of them sometimes.
A unit's predicted seconds are the cheaper of its stored time (its own path) and its cheaper
path's prediction (verify_sample.sh), and it is recomputed by that path.  Units above
--max-unit have no chance in make test (one could outlast the suite); make verify-store-full
recomputes them.  Whether a unit is drawn is decided by a hash of the seed
(the revision) and the unit, uniform in [0, 1) against p, so a revision's sample is fixed and
successive revisions draw independently.

stdin: verify_sample.sh's candidates (file, program, args, level, weight, stored s, thetas,
cheaper path's options or "-", its predicted s).
stdout: the drawn units (file, program, args, level, weight, stored s, thetas, the path's
options or "-" for its own), in hash order.  stderr: one summary line.
--coverage N: instead of drawing, print the coverage per run and after N runs, expected from
the chances and counted over N seeds (seed.1 … seed.N).
"""
import argparse
import hashlib
import sys


def uniform(seed, unit):
    h = hashlib.md5(("%s\t%s" % (seed, unit)).encode()).hexdigest()
    return int(h[:13], 16) / float(16 ** 13)


def tau_for(costs, budget):
    """The tau whose expected run cost sum min(c, tau) equals the budget (all, if they fit)."""
    if sum(costs) <= budget:
        return max(costs, default=0.0)
    lo, hi = 0.0, max(costs)
    for _ in range(200):
        mid = (lo + hi) / 2
        if sum(min(c, mid) for c in costs) > budget:
            hi = mid
        else:
            lo = mid
    return lo


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seed", required=True)
    ap.add_argument("--budget", type=float, default=60.0, help="expected seconds a run recomputes")
    ap.add_argument("--max-unit", type=float, default=60.0, help="stored seconds above which a unit is never drawn")
    ap.add_argument("--overhead", type=float, default=2.0, help="seconds a unit costs besides its stored time")
    ap.add_argument("--slow", type=float, default=2.0, help="recomputation time per stored second")
    ap.add_argument("--coverage", type=int, default=0, help="runs to count coverage over (no draw)")
    a = ap.parse_args()
    for name in ("budget", "max_unit", "overhead", "slow"):
        if not getattr(a, name) > 0:
            sys.exit("sample_draw.py: --%s %r must be positive" % (name.replace("_", "-"), getattr(a, name)))

    units = []  # (the unit as drawn: its first 7 columns and its path, predicted seconds)
    for line in sys.stdin:
        f = line.rstrip("\n").split("\t")
        if len(f) < 7:
            continue
        own = float(f[5])
        if len(f) >= 9 and f[7] != "-" and float(f[8]) < own:
            units.append((f[:7] + [f[7]], float(f[8])))
        else:
            units.append((f[:7] + ["-"], own))
    reach = [(f, a.overhead + a.slow * s) for f, s in units if s <= a.max_unit]
    tau = tau_for([c for _, c in reach], a.budget)
    chance = [(f, min(1.0, tau / c)) for f, c in reach]
    key = lambda f: "\t".join(f[:5])  # file, program, args, level, weight
    n_all, n_reach = len(units), len(reach)
    expected = sum(p for _, p in chance)

    if a.coverage:
        n = a.coverage
        exp_after = sum(1 - (1 - p) ** n for _, p in chance)
        seen, per_run = set(), []
        for r in range(1, n + 1):
            drawn = [key(f) for f, p in chance if uniform("%s.%d" % (a.seed, r), key(f)) < p]
            per_run.append(len(drawn))
            seen.update(drawn)
        cost_all = sum(s for _, s in units)
        cost_reach = sum(s for f, s in units if s <= a.max_unit)
        by_path = sum(1 for f, s in units if s <= a.max_unit and f[7] != "-")
        print("units\t%d\nreachable\t%d\nreachable_by_cheaper_path\t%d\nreachable_predicted_s\t%.0f\nall_predicted_s\t%.0f" % (
            n_all, n_reach, by_path, cost_reach, cost_all))
        print("min_chance\t%.5f\nexpected_per_run\t%.1f\ncounted_per_run_mean\t%.1f" % (
            min((p for _, p in chance), default=0), expected, sum(per_run) / n))
        print("runs\t%d\nexpected_after_runs\t%.1f\ncounted_after_runs\t%d" % (n, exp_after, len(seen)))
        return

    drawn = sorted((u, f) for f, p in chance for u in [uniform(a.seed, key(f))] if u < p)
    for _, f in drawn:
        sys.stdout.write("\t".join(f) + "\n")
    sys.stderr.write("%d of %d reachable units drawn (expected %.1f a run; every reachable unit's chance >= %.4f; "
                     "%d units above %g predicted s never drawn here)\n" % (
                         len(drawn), n_reach, expected, min((p for _, p in chance), default=0),
                         n_all - n_reach, a.max_unit))


if __name__ == "__main__":
    main()
