#!/usr/bin/env python3
"""A localization run's poses (localization.csv) against a trajectory of the same map's frame
at the same stamps, per state (scripts/bench-localize.sh section 4): how many scans of each
state, and for those the trajectory has, the distance's median, 95th percentile and maximum.

usage: localization-errors.py LOCALIZATION_CSV TRAJECTORY_TUM
"""
import csv
import math
import sys


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    reference = {}
    for line in open(sys.argv[2]):
        if line.startswith('#') or not line.strip():
            continue
        v = [float(x) for x in line.split()]
        reference[round(v[0], 4)] = (v[1], v[2])
    counts, errors = {}, {}
    for r in rows:
        counts[r['state']] = counts.get(r['state'], 0) + 1
        ref = reference.get(round(float(r['time']), 4))
        if r['state'] == 'lost' or ref is None:
            continue
        errors.setdefault(r['state'], []).append(math.hypot(float(r['x']) - ref[0], float(r['y']) - ref[1]))
    print('   scans: ' + ', '.join('%s %d' % (s, counts.get(s, 0)) for s in ('tracked', 'relocalized', 'predicted', 'lost')))
    for state in ('tracked', 'relocalized', 'predicted'):
        e = sorted(errors.get(state, []))
        if e:
            print('   %s, against the trajectory (%d scans it has): median %.3f m, p95 %.3f m, max %.3f m'
                  % (state, len(e), e[len(e) // 2], e[min(len(e) - 1, int(0.95 * len(e)))], e[-1]))


if __name__ == '__main__':
    main()
