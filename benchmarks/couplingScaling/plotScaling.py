#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Charts of the coupling benchmark (results.dat written by Allrun).

    plotScaling.py results.dat OUTDIR

sizes-<scene>.png : timing split DEM / CFD / coupling against the particle count,
            and the coupling cost per particle per coupling step (its parts)
strong-<scene>.png: speed-up and parallel efficiency (whole run and coupling) of
            each exchange against the rank count, particles held per rank
Prints the tables it draws. Rows repeated for the same configuration: the
last one counts.
"""
import sys
import os
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

cols = ("mode N cells ranks exchange steps total DEM CFD coupling exchangeTime "
        "locate voidFraction forces usPerParticleStep heldMin heldMax").split()


def read(path):
    rows = {}
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        v = line.split()
        r = dict(zip(cols, v))
        for k in cols:
            if k not in ("mode", "exchange"):
                r[k] = float(r[k])
        rows[(r["mode"], r["N"], r["ranks"], r["exchange"])] = r
    return list(rows.values())


def sizes(rows, out, mode):
    rows = sorted([r for r in rows if r["mode"] == mode], key=lambda r: r["N"])
    if not rows:
        return
    print("== %s" % mode)
    print("# particles cells  total[s]  DEM[s]  CFD[s]  coupling[s] (share)  "
          "us/particle/step: coupling exchange locate voidFraction forces")
    for r in rows:
        ps = r["N"]*r["steps"]
        print("%9d %7d %8.2f %7.2f %7.2f %7.2f (%4.1f %%)   %6.3f %6.3f %6.3f %6.3f %6.3f" % (
            r["N"], r["cells"], r["total"], r["DEM"], r["CFD"], r["coupling"],
            100*r["coupling"]/r["total"], 1e6*r["coupling"]/ps,
            1e6*r["exchangeTime"]/ps, 1e6*r["locate"]/ps,
            1e6*r["voidFraction"]/ps, 1e6*r["forces"]/ps))
    big = [r for r in rows if r["N"] >= 1e4]
    if big:
        us = [1e6*r["coupling"]/(r["N"]*r["steps"]) for r in big]
        mean = sum(us)/len(us)
        print("coupling per particle per step for N >= 1e4: %.3f ... %.3f us "
              "(mean %.3f, spread %+.0f %% / %+.0f %%)" % (
                  min(us), max(us), mean, 100*(min(us)/mean - 1),
                  100*(max(us)/mean - 1)))

    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    N = [r["N"] for r in rows]
    for key, style in (("total", "k-o"), ("DEM", "b-s"), ("CFD", "g-^"),
                       ("coupling", "r-D")):
        ax[0].loglog(N, [r[key] for r in rows], style, label=key)
    ax[0].loglog(N, [rows[-1]["coupling"]*n/N[-1] for n in N], "r:",
                 label="linear in N")
    ax[0].set_xlabel("particles")
    ax[0].set_ylabel("wall time [s] (%d coupling steps)" % rows[0]["steps"])
    ax[0].set_title("Timing split, serial (%s)" % mode[6:])
    ax[0].grid(True, which="both", alpha=0.3)
    ax[0].legend()
    for key, style in (("coupling", "r-D"), ("locate", "c-o"),
                       ("voidFraction", "m-s"), ("forces", "y-^"),
                       ("exchangeTime", "k-v")):
        ax[1].semilogx(N, [1e6*r[key]/(r["N"]*r["steps"]) for r in rows],
                       style, label=key)
    ax[1].set_xlabel("particles")
    ax[1].set_ylabel("us per particle per coupling step")
    ax[1].set_title("Coupling cost per particle")
    ax[1].set_ylim(bottom=0)
    ax[1].axvspan(1e4, 1e6, color="0.9", zorder=0)
    ax[1].grid(True, which="both", alpha=0.3)
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, mode + ".png"), dpi=110)


def strong(rows, out, mode):
    rows = [r for r in rows if r["mode"] == mode]
    if not rows:
        return
    print("== %s" % mode)
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2))
    print("# exchange ranks particles total[s] coupling[s] speed-up(total) "
          "efficiency(total) efficiency(coupling) held/rank(max)")
    for e, style in (("allReduce", "b-o"), ("manyToMany", "r-s")):
        rs = sorted([r for r in rows if r["exchange"] == e], key=lambda r: r["ranks"])
        if not rs:
            continue
        base = [r for r in rs if r["ranks"] == rs[0]["ranks"]][0]
        p0 = base["ranks"]
        P = [r["ranks"] for r in rs]
        sT = [base["total"]/r["total"] for r in rs]
        eT = [s*p0/p for s, p in zip(sT, P)]
        eC = [base["coupling"]*p0/(p*r["coupling"]) for r, p in zip(rs, P)]
        for r, s, a, b in zip(rs, sT, eT, eC):
            print("%-10s %3d %8d %8.2f %8.2f %6.2f %6.2f %6.2f %8d" % (
                e, r["ranks"], r["N"], r["total"], r["coupling"], s, a, b,
                r["heldMax"]))
        ax[0].plot(P, sT, style, label=e)
        ax[1].plot(P, eC, style, label=e + ": coupling")
        ax[1].plot(P, eT, style[0] + ":", label=e + ": whole run")
        ax[2].plot(P, [r["heldMax"] for r in rs], style, label=e)
    P = sorted(set(r["ranks"] for r in rows))
    ax[0].plot(P, [p/P[0] for p in P], "k:", label="ideal")
    ax[0].set_title("Speed-up (whole run)")
    ax[1].axhline(0.7, color="k", ls="--", lw=0.8)
    ax[1].set_title("Parallel efficiency")
    ax[1].set_ylim(0, 1.2)
    ax[2].set_title("Particles held per rank (max)")
    ax[2].set_yscale("log")
    for a in ax:
        a.set_xlabel("MPI ranks")
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, mode + ".png"), dpi=110)


if __name__ == "__main__":
    rows = read(sys.argv[1])
    out = sys.argv[2] if len(sys.argv) > 2 else "."
    for mode in sorted(set(r["mode"] for r in rows)):
        if mode.startswith("sizes"):
            sizes(rows, out, mode)
        elif mode.startswith("strong"):
            strong(rows, out, mode)
