#!/usr/bin/env python3
"""Strong and weak scaling of swarf's domain decomposition to 64-1024 ranks, modelled from the
figures measured on this machine (README.md, "W1 over MPI ranks by domain decomposition").

The model, per rank and step (one rank per core, W1: a bonded FCC block, 4 particles per cell):
  compute  = t_c * (n_own + g)             every owned particle and every ghost is stepped, and the
                                           rods with one end in the halo are evaluated on both sides
  exchange = m * alpha + 72 B * g / beta   m messages per step (the halo: position, velocity and
           + t_g * g                       acceleration of each ghost, 72 B), t_g per ghost to pack,
           + ceil(log2 P) * alpha          unpack and wait; one small collective per step (the stray
                                           check)
  ghosts g = 2 * (cells across a face)^2 per face of the busiest rank's domain (two FCC lattice planes: measured 578 at 17^3 and
             7,938 at 63^3 per cut face, both exactly 2 n^2)
Decompositions: slabs along x (`--partition slabs`: 2 faces, m = 2) and boxes from recursive
coordinate bisection (`--partition rcb`, Zoltan's RCB, the default of `mpirun -n N swarf run` since
2026-12-07: 6 faces, m = 6 with LAMMPS's staged exchange, which forwards the edge and corner
ghosts; swarf's halo sends to each box within reach directly, up to 26 messages, which the model's
m = 6 understates). The ghost count checked against the engine (README.md, "Boxes from Zoltan's
recursive coordinate bisection", W1 31^3): slabs exactly 2 n^2 per face; RCB at 8 ranks 1,488
measured against 1,442 modelled (the edges add 3 %).
Measured inputs (W1, this 2-core machine, 2026-12-06): t_c = 44 ns (17^3, 1 thread, 43.2-46.4) and
57 ns (63^3, 55-59); t_g = 170 ns per ghost as measured on 2 ranks here (88-104 us per step of
exchange for 578 ghosts, which includes waiting on the other rank), or 20 ns at memory speed
(72 B packed and unpacked at a few GB/s).
Network assumed (not measured here): InfiniBand HDR100, alpha = 1.5 us, beta = 12 GB/s; and
10 Gb Ethernet with MPI over TCP, alpha = 20 us, beta = 1.1 GB/s.
Efficiency E(P) = T(1) / (P * T(P)); T(1) = t_c * N.

A cut with bond formation adds a term that does not shrink with P (README.md, "The domains'
serial bookkeeping", 2026-12-07): every rank gathers the run's pressed pairs and the reports of
their particles each step (two all-gathers) and replays the serial rule on all of them,
  formation = 2 ceil(log2 P) alpha + B_f * pairs / beta + t_r * pairs
with pairs = 207 per step per 0.08 mm of chip width (the default cut at 10 layers across h =
0.2 mm, measured from 1 mm of travel on), B_f = 136 B per pair (40 B a pair, 48 B per report,
409 reports for 207 pairs) and t_r = 0.15 us per pair to sort and replay (estimated from perf:
not measured apart), beside the cut's own t_c = 160 ns per particle-step on one core (the
checkpoint at 1 mm on 1 thread, 145-165 ns) and W1's halo model for the same number of particles.

Usage: scaling_model.py [OUT.png]   prints the tables (markdown) and writes the plot.
"""
import math
import sys

T_C = {17: 44e-9, 63: 57e-9, "large": 57e-9}  # s per particle-step, one core
T_G = {"as measured here": 170e-9, "halo at memory speed": 20e-9}  # s per ghost and step
NETS = {"InfiniBand HDR100": (1.5e-6, 12e9), "10 GbE (TCP)": (20e-6, 1.1e9)}
BYTES_PER_GHOST = 72
# The cut with bond formation (docstring): measured on the default cut, 2026-12-07.
T_C_CUT = 160e-9  # s per particle-step, one core
PAIRS_PER_MM = 207 / 0.08  # pressed pairs per step per mm of chip width
BYTES_PER_PAIR = 136  # B gathered per pressed pair (pair and its particles' reports)
T_REPLAY = 0.15e-6  # s per pressed pair to sort and replay, on every rank


def step_time(n_cells, ranks, decomposition, t_c, t_g, alpha, beta):
    """Seconds per step on the busiest rank for a cube of n_cells^3 FCC cells over 'ranks'."""
    n = 4.0 * n_cells**3
    own = n / ranks
    if ranks == 1:
        return t_c * n, 0.0
    # The busiest rank's faces: a slab or box at an end of the block has fewer; with 2 ranks each
    # has one face (measured: 578 ghosts per rank at 17^3, one face of 2 * 17^2).
    if decomposition == "slabs":
        faces = 1 if ranks == 2 else 2
        messages, face_cells = faces, n_cells
        if n_cells / ranks < 1.0:  # a slab thinner than one cell: its ghosts outnumber its particles
            return math.nan, math.nan
    else:
        side = n_cells / ranks ** (1.0 / 3.0)
        faces = {2: 1, 4: 2, 8: 3}.get(ranks, 6)  # (RCB halves one axis per level; from 27 ranks on, interior boxes)
        messages, face_cells = faces, side
        if side < 1.0:
            return math.nan, math.nan
    ghosts = faces * 2.0 * face_cells**2
    compute = t_c * (own + ghosts)
    exchange = messages * alpha + BYTES_PER_GHOST * ghosts / beta + t_g * ghosts
    exchange += math.ceil(math.log2(ranks)) * alpha
    return compute, exchange


def cut_efficiency(particles, width_mm, ranks, t_g, alpha, beta):
    """Strong-scaling efficiency of a cut of 'particles' with a chip 'width_mm' wide: W1's halo model
    for a cube of as many particles (boxes), at the cut's t_c, plus bond formation's replay."""
    cells = (particles / 4.0) ** (1.0 / 3.0)
    if ranks == 1:
        return 1.0
    c, e = step_time(cells, ranks, "boxes (RCB)", T_C_CUT, t_g, alpha, beta)
    pairs = PAIRS_PER_MM * width_mm
    formation = 2 * math.ceil(math.log2(ranks)) * alpha + BYTES_PER_PAIR * pairs / beta + T_REPLAY * pairs
    return T_C_CUT * particles / (ranks * (c + e + formation))


def efficiency(n_cells, ranks, decomposition, t_c, t_g, alpha, beta):
    c, e = step_time(n_cells, ranks, decomposition, t_c, t_g, alpha, beta)
    return t_c * 4.0 * n_cells**3 / (ranks * (c + e))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "scaling_model.png"
    ranks = [2, 64, 128, 256, 512, 1024]
    # Check against the two measured points (2 ranks on one machine: shared memory, alpha ~ 1 us,
    # beta ~ 5 GB/s).
    print("## The model at the measured points (2 ranks, shared memory: alpha 1 us, beta 5 GB/s)\n")
    print("| scene | t_g | modelled ns/particle-step | efficiency |")
    print("|---|---|---|---|")
    for cells in (17, 63):
        for name, tg in T_G.items():
            c, e = step_time(cells, 2, "slabs", T_C[cells], tg, 1e-6, 5e9)
            n = 4 * cells**3
            print(f"| W1 {cells}^3 | {name} | {(c + e) / n * 1e9:.1f} | {T_C[cells] * n / (2 * (c + e)):.2f} |")
    print()
    print("## Strong scaling: a fixed block over P ranks (efficiency)\n")
    cases = [(63, "1 M particles (63^3)"), (160, "16.4 M particles (160^3)")]
    header = "| block | decomposition | network | t_g | " + " | ".join(f"P={p}" for p in ranks) + " |"
    print(header)
    print("|" + "---|" * (4 + len(ranks)))
    curves = []
    for cells, label in cases:
        for dec in ("slabs", "boxes (RCB)"):
            for net, (a, b) in NETS.items():
                for tgn, tg in T_G.items():
                    e = [efficiency(cells, p, dec, T_C["large"], tg, a, b) for p in ranks]
                    cells_txt = " | ".join("-" if math.isnan(x) else f"{x:.2f}" for x in e)
                    print(f"| {label} | {dec} | {net} | {tgn} | {cells_txt} |")
                    curves.append((label, dec, net, tgn, e))
    print()
    print("## Weak scaling: a fixed number of particles per rank, boxes (RCB) (efficiency)\n")
    print("| per rank | network | t_g | " + " | ".join(f"P={p}" for p in ranks) + " |")
    print("|" + "---|" * (3 + len(ranks)))
    for per_rank in (1e5, 1e6):
        for net, (a, b) in NETS.items():
            for tgn, tg in T_G.items():
                row = []
                for p in ranks:
                    cells = (per_rank * p / 4.0) ** (1.0 / 3.0)
                    row.append(efficiency(cells, p, "boxes (RCB)", T_C["large"], tg, a, b))
                print(f"| {per_rank:.0e} | {net} | {tgn} | " + " | ".join(f"{x:.2f}" for x in row) + " |")
    print()
    print("## A 3D cut with bond formation, strong scaling (boxes; efficiency)\n")
    print("| cut | network | t_g | " + " | ".join(f"P={p}" for p in ranks) + " | formation's share at P=1024 |")
    print("|" + "---|" * (4 + len(ranks)))
    for particles, width, label in ((5e6, 1.0, "5 M particles, chip 1 mm wide"), (5e7, 3.0, "50 M, 3 mm wide")):
        for net, (a, b) in NETS.items():
            for tgn, tg in T_G.items():
                row = [cut_efficiency(particles, width, p, tg, a, b) for p in ranks]
                cells = (particles / 4.0) ** (1.0 / 3.0)
                c, e = step_time(cells, 1024, "boxes (RCB)", T_C_CUT, tg, a, b)
                pairs = PAIRS_PER_MM * width
                f = 2 * math.ceil(math.log2(1024)) * a + BYTES_PER_PAIR * pairs / b + T_REPLAY * pairs
                share = f / (c + e + f)
                print(f"| {label} | {net} | {tgn} | " + " | ".join(f"{x:.2f}" for x in row) + f" | {share:.2f} |")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("\n(matplotlib missing: no plot)")
        return
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    ps = [2**k for k in range(1, 11)]
    for k, (cells, label) in enumerate(cases):
        for dec, style in (("slabs", "--"), ("boxes (RCB)", "-")):
            for tgn, tg in T_G.items():
                a, b = NETS["InfiniBand HDR100"]
                e = [efficiency(cells, p, dec, T_C["large"], tg, a, b) for p in ps]
                ax[k].plot(ps, e, style, marker="o", ms=3, label=f"{dec}, t_g {tgn}")
        ax[k].set_xscale("log", base=2)
        ax[k].set_ylim(0, 1.05)
        ax[k].set_xlabel("MPI ranks (one per core)")
        ax[k].set_ylabel("parallel efficiency")
        ax[k].set_title(f"W1 {label}: strong scaling, model\n(InfiniBand HDR100)", fontsize=10)
        ax[k].grid(True, alpha=0.3)
        ax[k].legend(fontsize=7)
    # Measured at 63^3 on 2 ranks of this machine (README.md): 0.88-0.95 in a quiet sitting.
    ax[0].errorbar([2], [0.915], yerr=[[0.035], [0.035]], fmt="k*", ms=9, label="measured, 2 ranks here")
    ax[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"\nplot: {out}")


if __name__ == "__main__":
    main()
