#!/usr/bin/env python3
"""Load-balance efficiency (mean / max busy time of the ranks) of geovis's cost-ordered tiles
against GeoViS-style stripes, simulated from measured per-tile costs.

Input: the CSV that `geovis render --tile-stats FILE` writes (one line per rendered tile: its
rectangle, the rank that rendered it, the cost it was ordered by, and its CPU seconds). Render
once with one rank to measure the costs, then:

  scripts/simulate_load_balance.py tiles.csv --ranks 2,4,8,64,512

  cost-ordered: the tiles, most expensive first by the cost they were ordered by (column
                order_cost: the probe for the first frame; with --order-from PREV.csv the CPU
                seconds a previous render measured, as for the next frame of a sequence), each go
                to the rank that becomes free first; a rank is busy for the tile's measured CPU
                seconds. This is what rank 0 of `mpirun -np N geovis render` does, without the
                communication.
  stripes:      the image split into N horizontal stripes of (nearly) equal height, one per rank,
                as GeoViS's gvsRenderPar does; a tile's cost is spread evenly over its rows.

With --measured, the files are the --tile-stats of real N-rank runs instead, and the efficiency
of what each rank actually did (the rank column) is printed: from the CPU seconds of its tiles
(unequal when the ranks get unequal shares of shared cores: then a dynamic schedule rightly gives
the faster rank more tiles) and from the wall time at which its last tile came back.
"""
import argparse
import csv
import heapq
import sys
from collections import defaultdict


def read_tiles(path, frame):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if int(r["frame"]) == frame and int(r["eye"]) == 0]
    if not rows:
        sys.exit(f"{path}: no tiles of frame {frame}")
    tiles = []
    for r in rows:
        tiles.append({k: (float(v) if k in ("order_cost", "cpu_seconds", "done_at") else int(v))
                      for k, v in r.items()})
    return tiles


def efficiency(busy):
    busy = list(busy)
    return (sum(busy) / len(busy)) / max(busy) if max(busy) > 0 else 1.0


def cost_ordered(tiles, ranks, order):
    queue = sorted(tiles, key=lambda t: (-order[t["tile"]], t["tile"]))
    free = [(0.0, r) for r in range(ranks)]  # (time the rank becomes free, rank)
    busy = [0.0] * ranks
    for t in queue:
        at, r = heapq.heappop(free)
        busy[r] += t["cpu_seconds"]
        heapq.heappush(free, (at + t["cpu_seconds"], r))
    return efficiency(busy)


def stripes(tiles, ranks):
    height = max(t["y1"] for t in tiles)
    row_cost = [0.0] * height
    for t in tiles:
        for y in range(t["y0"], t["y1"]):
            row_cost[y] += t["cpu_seconds"] / (t["y1"] - t["y0"])
    busy = [0.0] * ranks
    for r in range(ranks):  # rows [r*H/N, (r+1)*H/N); with N > H some ranks get no rows
        for y in range(r * height // ranks, (r + 1) * height // ranks):
            busy[r] += row_cost[y]
    return efficiency(busy)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("stats", nargs="+", help="--tile-stats CSV file(s)")
    ap.add_argument("--ranks", default="2,4,8,64,512", help="rank counts to simulate (comma-separated)")
    ap.add_argument("--frame", type=int, default=0, help="frame of the CSV to use")
    ap.add_argument("--order-from", help="order by the CPU seconds of this earlier --tile-stats file")
    ap.add_argument("--measured", action="store_true", help="report the ranks' measured busy time instead")
    a = ap.parse_args()

    if a.measured:
        print("| file | ranks | tiles per rank (min-max) | busy CPU s per rank (min / mean / max) "
              "| CPU efficiency | last tile back, s (min / max) | wall efficiency |")
        print("|---|---|---|---|---|---|---|")
        for path in a.stats:
            tiles = read_tiles(path, a.frame)
            busy, count, last = defaultdict(float), defaultdict(int), defaultdict(float)
            for t in tiles:
                busy[t["rank"]] += t["cpu_seconds"]
                count[t["rank"]] += 1
                last[t["rank"]] = max(last[t["rank"]], t["done_at"])
            b, w = list(busy.values()), list(last.values())
            print(f"| {path} | {len(b)} | {min(count.values())}-{max(count.values())} "
                  f"| {min(b):.3f} / {sum(b) / len(b):.3f} / {max(b):.3f} | {100 * efficiency(b):.1f} % "
                  f"| {min(w):.2f} / {max(w):.2f} | {100 * efficiency(w):.1f} % |")
        return

    tiles = read_tiles(a.stats[0], a.frame)
    order = {t["tile"]: t["order_cost"] for t in tiles}
    if a.order_from:
        order = {t["tile"]: t["cpu_seconds"] for t in read_tiles(a.order_from, a.frame)}
        missing = [t["tile"] for t in tiles if t["tile"] not in order]
        if missing:
            sys.exit(f"{a.order_from}: has no cost for tiles {missing[:5]}...")
    total = sum(t["cpu_seconds"] for t in tiles)
    print(f"{len(tiles)} tiles, {total:.2f} CPU s in all, costliest tile {max(t['cpu_seconds'] for t in tiles):.4f} s")
    print("| ranks | tiles per rank | cost-ordered tiles | stripes |")
    print("|---|---|---|---|")
    for n in (int(x) for x in a.ranks.split(",")):
        print(f"| {n} | {len(tiles) / n:.1f} | {100 * cost_ordered(tiles, n, order):.1f} % "
              f"| {100 * stripes(tiles, n):.1f} % |")


if __name__ == "__main__":
    main()
