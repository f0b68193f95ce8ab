"""What a cell asks a cluster scheduler for (docs/sweeps.md, "Running on a cluster"): memory and
wall time estimated from the cell before it runs, so that an 8,192-node cell is not killed for
a default too small and a scene0 cell does not hold gigabytes.

./simulate has no host-memory estimate of its own; the bound is derived from the platform's
size (every node is a SimGrid host with its actors and mailboxes), from
peak resident sizes measured with /usr/bin/time -f %M on the Release build (November 2026):
  scene0, R=1 V=1, ncube2.json (64 nodes)         55 MB
  scene0, R=16 V=63, ncube2-d10.json (1,024)     117 MB
  scene0, R=8 V=63, ncube2-d13.json (8,192)      229 MB
and the 2 GB a prediction sweep's 8,192-node cell of a large scene takes. The
request is that bound with a margin: a base (ncube.run_cell beside ./simulate, and what a
job's own Snakemake took before the sweep's job script ran the cell without one) and a quarter MB per platform node (about eight
times the measured growth, which also covers larger scenes' elements), rounded up to 64 MB."""
import math

BASE_MB = 384              # run_cell, ./simulate's 55 MB base, and the ~120 MB a job's own
                           # Snakemake took (at 192 MB, 2 cells of the Slurm test failed in 1 of 3
                           # runs then): kept as margin
PER_NODE_MB = 0.25         # 8,192 nodes -> 2 GB, the largest cell measured
BASE_MINUTES = 10          # a cell of the paper's sweeps takes 1-60 s
NODES_PER_MINUTE = 128     # 8,192 nodes: about an hour more


def memory_mb(cell):
    estimate = BASE_MB + PER_NODE_MB * cell.nodes
    if cell.trace:         # the timeline is held until written
        estimate *= 2
    return int(math.ceil(estimate / 64) * 64)


def runtime_minutes(cell):
    minutes = BASE_MINUTES + cell.nodes / NODES_PER_MINUTE
    if cell.trace:
        minutes *= 2
    return int(math.ceil(minutes))


def request(cell):
    """{"mem_mb": ..., "runtime": minutes}: Snakemake's resource names, passed to sbatch."""
    return {"mem_mb": memory_mb(cell), "runtime": runtime_minutes(cell)}
