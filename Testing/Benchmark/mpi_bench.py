"""What ranks buy on ParaView's MPI server (issue 11): the same solve on 1 rank and on R
ranks, one thread each, and what the ranks send each other.

./relight bench mpi [--elements 230000] [--ranks 2] [--repeats 3] [--scene Data/paper_8lights.vtp]

Runs `mpiexec -np 1` and `-np R` pvbatch alternately, `repeats` times, and takes each one's
fastest run (this machine's neighbours make single runs noisy). Prints the solve times, the
speed-up, each rank's share of the receivers, the sums per shot and their bytes, and a model
of 16 and 64 ranks built from these figures."""

import argparse
import math
import os
import re
import shutil
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
SHARE = re.compile(r"rank (\d+) of (\d+) received for (\d+) of (\d+) elements and cast (\d+) rays; (\d+) sums over "
                   r"the ranks, (\d+) bytes per shot, ([\d.]+) MB in all, ([\d.]+) s in sums")
SHOTS = re.compile(r"; (\d+) shots, ([\d.]+) s;")


def run(ranks, scene, elements, threads):
    """(wall seconds, elements, [per-rank share dicts], shots) of one mpiexec run."""
    command = [shutil.which("mpiexec"), "--allow-run-as-root", "--oversubscribe", "-np", str(ranks),
               "pvbatch", "--mpi", os.path.join(HERE, "mpi_rank.py"), scene, str(elements), str(threads)]
    done = subprocess.run(command, capture_output=True, text=True, timeout=3600)
    log = done.stdout + done.stderr
    found = re.search(r"BENCH solve ([\d.]+) s, (\d+) elements", log)
    if done.returncode != 0 or not found:
        raise SystemExit(f"the {ranks}-rank run failed:\n{log[-3000:]}")
    shares = [dict(zip(("rank", "ranks", "mine", "total", "rays", "sums", "shot_bytes", "mb", "sum_seconds"),
                       (float(x) for x in m))) for m in SHARE.findall(log)]
    shots = int(SHOTS.search(log).group(1))
    return float(found.group(1)), int(found.group(2)), sorted(shares, key=lambda s: s["rank"]), shots


def model(serial, parallel, ranks, shots, shares, elements, lights=8):
    """Predicted solve seconds on n ranks: D + C / n + communication + imbalance. D (work
    every rank repeats) and C (work the ranks divide) come from the two measured runs. A sum
    over n ranks costs latency x log2(n) (a tree reduction), the latency taken from the
    rank that waited least (its time in sums is transfers, not waiting), plus its bytes
    over 10 GB/s (an assumption; InfiniBand HDR moves 25 GB/s). Imbalance, the extra wait of
    the rank that waited most, is kept at its measured share of the divided work per rank."""
    sums = shares[0]["sums"]
    waits = [s["sum_seconds"] for s in shares]
    latency = min(waits) / (sums * max(math.log2(ranks), 1))
    imbalance = max(waits) - min(waits)
    compute = parallel - max(waits)
    divided = (serial - compute) * ranks / (ranks - 1)
    repeated = serial - divided
    rows = []
    for n in (ranks, 16, 64):
        per_shot_bytes = 8 * n * (5 + lights + 3 * lights)  # the shot's table: a row per rank
        final_bytes = 8 * 3 * lights * elements
        comm = sums * latency * math.log2(n) + (shots * per_shot_bytes + final_bytes) / 10e9 * math.log2(n)
        rows.append((n, repeated + divided / n + comm + imbalance * ranks / n, per_shot_bytes, comm))
    return repeated, divided, latency, imbalance, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scene", default=os.path.join(HERE, "..", "..", "Data", "paper_8lights.vtp"))
    parser.add_argument("--elements", type=int, default=230000)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    best = {}
    for repeat in range(args.repeats):
        for ranks in (1, args.ranks):
            seconds, elements, shares, shots = run(ranks, args.scene, args.elements, args.threads)
            print(f"  run {repeat + 1}: {ranks} rank(s) x {args.threads} thread(s): {seconds:.2f} s", flush=True)
            if ranks not in best or seconds < best[ranks][0]:
                best[ranks] = (seconds, elements, shares, shots)
    serial, elements, _, shots = best[1]
    parallel, _, shares, _ = best[args.ranks]
    print(f"\n{elements} elements, {shots} shots, {args.threads} thread(s) per rank, fastest of {args.repeats} runs:")
    print(f"  1 rank: {serial:.2f} s   {args.ranks} ranks: {parallel:.2f} s   speed-up {serial / parallel:.2f}x")
    for s in shares:
        print(f"  rank {int(s['rank'])}: received for {int(s['mine'])} elements, cast {int(s['rays'])} rays, "
              f"{int(s['sums'])} sums ({s['sums'] / shots:.2f} per shot), {int(s['shot_bytes'])} bytes per shot, "
              f"{s['mb']:.1f} MB in all (the solution exchange included), {s['sum_seconds']:.2f} s in sums")
    repeated, divided, latency, imbalance, rows = model(serial, parallel, args.ranks, shots, shares, elements)
    print(f"\nModel from these figures: {repeated:.2f} s every rank repeats, {divided:.2f} s the ranks divide, "
          f"{latency * 1e6:.0f} us per sum and tree level, {imbalance:.2f} s of waiting for the slower rank")
    for n, seconds, per_shot, comm in rows:
        print(f"  {n:3d} ranks: {per_shot} bytes per shot, {comm:.2f} s communicating, predicted {seconds:.2f} s, "
              f"speed-up {serial / seconds:.1f}x")


if __name__ == "__main__":
    main()
