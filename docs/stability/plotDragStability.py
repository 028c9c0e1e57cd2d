#!/usr/bin/env python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Chart of etc/sceneMaps/dragStability.dat (runDragStability.sh): explicit
vs implicit drag in the DEM steps against the coupling interval over the
particle (or bed) response time. Writes dragStability.png here."""
import os
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
maps = os.path.join(here, "..", "..", "etc", "sceneMaps")
rows = [l.split() for l in open(os.path.join(maps, "dragStability.dat"))
        if l.strip() and not l.startswith("#")]
fig, axes = plt.subplots(1, 2, figsize=(10, 4))
for ax, scene, ylabel in (
        (axes[0], "settling", "terminal velocity: max(|mean error|, std) / v_t"),
        (axes[1], "bed", "plate pressure std / bed weight")):
    top = 1.0
    for scheme, style, dx in (("explicit", "o-", 0.97), ("implicit", "s--", 1.03)):
        r = [x for x in rows if x[0] == scene and x[1] == scheme]
        ratio = np.array([float(x[3]) for x in r])
        val = np.array([float(x[4]) if x[4] != "nan" else np.nan for x in r])
        blown = np.array([int(x[5]) for x in r])
        shown = np.where(blown == 0, val, np.nan)   # lines break at blow-ups
        line, = ax.loglog(ratio, shown, style, label=scheme + " drag")
        if np.any(blown == 1):
            ax.plot(ratio[blown == 1]*dx, [top]*int(np.sum(blown == 1)), "x",
                    color=line.get_color(), ms=9, mew=2,
                    label=scheme + ": blew up")
    ax.axvline(2.0, color="grey", lw=0.8)
    ax.text(2.0, 0.5, " dt = 2 tau", color="grey", fontsize=8,
            transform=ax.get_xaxis_transform())
    ax.set_xlabel("coupling interval / response time")
    ax.set_ylabel(ylabel)
    ax.set_title("settling 0.2 mm particle" if scene == "settling" else "packed bed at rest (2 mm)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(here, "dragStability.png"), dpi=110)
print("wrote", os.path.join(here, "dragStability.png"))
