"""What ranks buy on ParaView's MPI server: the same solve on 1 rank and on R
ranks, one thread each, and what the ranks send each other.

./relight bench mpi [--elements 230000] [--ranks 2] [--repeats 3] [--scene Data/paper_8lights.vtp] [--no-ceiling]

Runs `mpiexec -np 1` and `-np R` pvbatch alternately, `repeats` times, and takes each one's
fastest run (this machine's neighbours make single runs noisy). Each repeat also runs R
one-rank solves at once, pinned to R cores: R copies of the scene competing for cache and
memory as R ranks do, the ceiling R ranks could reach on this machine. Prints the solve times, the
speed-up, each rank's share of the receivers, the sums per shot and their bytes, the time of
one sum with every rank ready (mpi_latency.py), and a model of 16 and 64 ranks built from
these figures."""

import argparse
import math
import os
import re
import shutil
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
SHARE = re.compile(r"rank (\d+) of (\d+) received for (\d+) of (\d+) elements and cast (\d+) rays; (\d+) sums over "
                   r"the ranks, (\d+) bytes per shot, ([\d.]+) MB in all, ([\d.]+) s in sums")
SHOTS = re.compile(r"; (\d+) shots, ([\d.]+) s[ ;]")


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


def side_by_side(copies, scene, elements, threads):
    """Seconds of the slowest of `copies` one-rank solves run at once, each pinned to its own
    core: what this machine gives independent processes, the most R ranks could reach
    (R copies of the scene compete for cache and memory as R ranks do)."""
    command = lambda core: ["taskset", "-c", str(core), shutil.which("mpiexec"), "--allow-run-as-root",  # noqa: E731
                            "--bind-to", "none", "-np", "1", "pvbatch", "--mpi",
                            os.path.join(HERE, "mpi_rank.py"), scene, str(elements), str(threads)]
    running = [subprocess.Popen(command(c % os.cpu_count()), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True) for c in range(copies)]
    slowest = 0.0
    for process in running:
        log = process.communicate(timeout=3600)[0]
        found = re.search(r"BENCH solve ([\d.]+) s", log)
        if process.returncode != 0 or not found:
            raise SystemExit(f"a side-by-side run failed:\n{log[-3000:]}")
        slowest = max(slowest, float(found.group(1)))
    return slowest


def latency(ranks):
    """Seconds of one sum over `ranks` ranks when all are waiting for it (mpi_latency.py)."""
    command = [shutil.which("mpiexec"), "--allow-run-as-root", "--oversubscribe", "-np", str(ranks),
               "pvbatch", "--mpi", "--symmetric", os.path.join(HERE, "mpi_latency.py")]
    done = subprocess.run(command, capture_output=True, text=True, timeout=600)
    found = re.search(r"LATENCY ([\d.]+) us", done.stdout + done.stderr)
    if not found:
        raise SystemExit(f"the latency run failed:\n{(done.stdout + done.stderr)[-2000:]}")
    return float(found.group(1)) * 1e-6


def model(serial, parallel, ranks, shots, shares, elements, sum_latency, lights=8):
    """Predicted solve seconds on n ranks: D + C / n x (1 + u) + transfers x log2(n).
    Each rank's work is the run's time less its time in sums; their mean and the serial
    run give D (work every rank repeats) and C (work the ranks divide); u is how much the
    slowest rank's work exceeds the mean (kept at its measured share). A sum costs the
    latency measured with every rank ready, per level of a tree reduction, plus its bytes
    over 10 GB/s (an assumption; InfiniBand HDR moves 25 GB/s): the shot's table grows
    with n, the element factors shared at link-building shots do not."""
    work = [parallel - s["sum_seconds"] for s in shares]
    mean = sum(work) / len(work)
    divided = (serial - mean) * ranks / (ranks - 1)
    repeated = serial - divided
    imbalance = max(work) / mean - 1
    sums = shares[0]["sums"]
    table = lambda n: 8 * n * (5 + 4 * lights)  # noqa: E731  (a row per rank)
    shared = shares[0]["shot_bytes"] - table(ranks)  # element factors of link-building shots
    rows = []
    for n in (ranks, 16, 64):
        per_shot = table(n) + shared
        comm = math.log2(n) * (sums * sum_latency + (shots * per_shot + 8 * 3 * lights * elements) / 10e9)
        rows.append((n, repeated + divided / n * (1 + imbalance) + comm, per_shot, comm))
    return repeated, divided, imbalance, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scene", default=os.path.join(HERE, "..", "..", "Data", "paper_8lights.vtp"))
    parser.add_argument("--elements", type=int, default=230000)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--no-ceiling", dest="ceiling", action="store_false",
                        help="skip the side-by-side one-rank runs that measure the machine's own ceiling")
    args = parser.parse_args()
    best = {}
    pinned = None
    for repeat in range(args.repeats):
        for ranks in (1, args.ranks):
            seconds, elements, shares, shots = run(ranks, args.scene, args.elements, args.threads)
            print(f"  run {repeat + 1}: {ranks} rank(s) x {args.threads} thread(s): {seconds:.2f} s", flush=True)
            if ranks not in best or seconds < best[ranks][0]:
                best[ranks] = (seconds, elements, shares, shots)
        if args.ceiling and shutil.which("taskset"):
            seconds = side_by_side(args.ranks, args.scene, args.elements, args.threads)
            print(f"  run {repeat + 1}: {args.ranks} one-rank solves side by side: slowest {seconds:.2f} s", flush=True)
            pinned = seconds if pinned is None else min(pinned, seconds)
    serial, elements, _, shots = best[1]
    parallel, _, shares, _ = best[args.ranks]
    print(f"\n{elements} elements, {shots} shots, {args.threads} thread(s) per rank, fastest of {args.repeats} runs:")
    print(f"  1 rank: {serial:.2f} s   {args.ranks} ranks: {parallel:.2f} s   speed-up {serial / parallel:.2f}x")
    if pinned:
        ceiling = args.ranks * serial / pinned
        print(f"  {args.ranks} independent one-rank solves side by side: {pinned:.2f} s for the slowest, so this "
              f"machine runs {args.ranks} copies at {ceiling:.2f}x the throughput of one: the most {args.ranks} ranks "
              f"could reach here; the ranks reach {serial / parallel / ceiling:.0%} of it")
    for s in shares:
        print(f"  rank {int(s['rank'])}: received for {int(s['mine'])} elements, cast {int(s['rays'])} rays, "
              f"{int(s['sums'])} sums ({s['sums'] / shots:.2f} per shot), {int(s['shot_bytes'])} bytes per shot, "
              f"{s['mb']:.1f} MB in all (the solution exchange included), {s['sum_seconds']:.2f} s in sums")
    sum_latency = latency(args.ranks)
    repeated, divided, imbalance, rows = model(serial, parallel, args.ranks, shots, shares, elements, sum_latency)
    print(f"\nModel from these figures: {repeated:.2f} s every rank repeats, {divided:.2f} s the ranks divide, "
          f"the slowest rank does {100 * imbalance:.0f} % more than the mean, "
          f"{sum_latency * 1e6:.1f} us per sum with every rank ready")
    for n, seconds, per_shot, comm in rows:
        print(f"  {n:3d} ranks: {per_shot / 1e3:.1f} kB per shot, {comm:.2f} s in transfers, predicted {seconds:.2f} s, "
              f"speed-up {serial / seconds:.1f}x")


if __name__ == "__main__":
    main()
