#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""interDemFoam against OpenFOAM's DPMFoam: analysis of ./Allrun's runs.

  dpmCompare.py positions DPMFILE LIGGGHTSFILE
                                 the column's particle positions (a 2 mm
                                 lattice, each point moved at random by up to
                                 +-0.4 mm per direction, fixed seed) as a
                                 DPMFoam kinematicCloudPositions file and as
                                 LIGGGHTS create_atoms lines
  dpmCompare.py analyse RUNDIR   reads the runs in RUNDIR, writes
                                 RUNDIR/dpmFoamSettling.dat, dpmFoamColumn.dat,
                                 dpmFoamSettling.png, dpmFoamColumn.png and
                                 prints the tables

Physics of the references (seed Table 1: d = 1 mm, rho_p = 2500 kg/m3, water
1000 kg/m3, 1e-3 Pa s, g = 9.81 m/s2), no added mass, no history force:

 * single sphere from rest in still water, RK4 of
       rho_p V dv/dt = (rho_p - rho_f) V g - 1/2 Cd(Re) rho_f A v|v|
   with Schiller & Naumann, Cd Re = 24 (1 + 0.15 Re^0.687) (Re < 1000): the
   law of interDemFoam's SchillerNaumannDrag and of DPMFoam's WenYuDrag at
   alpha = 1. DPMFoam's WenYuDrag sees the host cell's alpha = 1 - V_p/V_cell
   (0.9918 for 1 mm in 4 mm cells): its own ODE is printed too.
 * suspension (batch settling, zero net volume flux): Richardson & Zaki,
   v = v_t eps^n, n from Garside & Al-Dibouni (1977)
   n = (5.1 + 0.27 Re_t^0.9)/(1 + 0.1 Re_t^0.9), and Richardson & Zaki's own
   n = 4.45 Re_t^-0.1 (1 < Re_t < 200, d/D -> 0), Re_t at v_t; plus the
   hindered settling velocity each drag closure implies on its own
   (force balance of a particle in the homogeneous suspension).
"""
import glob
import math
import os
import re
import sys

import numpy as np

D, RHO_P, RHO_F, MU, G = 1e-3, 2500.0, 1000.0, 1e-3, 9.81
VP = math.pi / 6 * D ** 3
AP = math.pi / 4 * D ** 2
DX = 4e-3                                  # cell size of both meshes

# The column's lattice: (i + 1/2) 2 mm, x, y < 24 mm, 40 mm < z < 80 mm,
# each point moved by a uniform random offset of up to +-JITTER per direction
# (seed 1): every particle stays in its 4 mm cell, but the particles no longer
# cross cell faces layer by layer at the same instant
LATTICE = 2e-3
NX, NY, NZ, Z0 = 12, 12, 20, 0.04
JITTER = 0.4e-3
MID = (0.05, 0.07)                          # the middle half, initial z


def cdre_sn(re):
    return 24 * (1 + 0.15 * re ** 0.687) if re < 1000 else 0.44 * re


def cdre_df(re):
    return (0.63 + 4.8 / math.sqrt(re)) ** 2 * re if re > 0 else 23.04


def chi_df(re):
    return 3.7 - 0.65 * math.exp(-(1.5 - math.log10(max(re, 1e-12))) ** 2 / 2)


def drag(w, eps, law):
    """Drag on one particle at interstitial slip w [m/s] in a suspension of
    fluid fraction eps, as the codes compute it (model A: interDemFoam, the
    particle also carries -V grad p; model B: DPMFoam, buoyancy only)."""
    if w <= 0:
        return 0.0
    re = RHO_F * w * D / MU
    if law == "SN":                    # interDemFoam SchillerNaumannDrag
        return cdre_sn(re) * math.pi * MU * D / 8 * w
    if law == "WenYuB":                # DPMFoam WenYuDrag
        return cdre_sn(eps * re) / eps * math.pi * MU * D / 8 * w * eps ** -2.65
    if law == "GidaspowA":             # interDemFoam GidaspowDrag, eps >= 0.8
        return cdre_sn(eps * re) * math.pi * MU * D / 8 * w * eps ** -2.65
    if law == "DiFeliceA":             # interDemFoam DiFeliceDrag
        rs = eps * re
        return 0.5 * cdre_df(rs) / rs * RHO_F * AP * eps ** (2 - chi_df(rs)) * w * w
    raise ValueError(law)


def bisect(f, lo=1e-9, hi=10.0):
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) > 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def terminal(law, eps=1.0):
    return bisect(lambda v: (RHO_P - RHO_F) * VP * G - drag(v, eps, law))


def hindered(law, eps):
    """Particle velocity of a homogeneous batch-settling suspension as the
    closure predicts it: interstitial slip w, particle velocity eps w (zero
    net volume flux). Model A: drag = eps (rho_p - rho_f) V g (the particle
    also carries the mixture's pressure gradient); model B: drag =
    (rho_p - rho_f) V g."""
    load = (RHO_P - RHO_F) * VP * G * (eps if law.endswith("A") else 1.0)
    w = bisect(lambda v: load - drag(v, eps, law))
    return eps * w


def ode(law, t_end, eps=1.0, dt=1e-5):
    """Sphere from rest, RK4; v downwards positive."""
    def acc(v):
        return ((RHO_P - RHO_F) * VP * G - drag(v, eps, law)) / (RHO_P * VP)
    n = int(round(t_end / dt))
    t = np.arange(n + 1) * dt
    v = np.zeros(n + 1)
    for i in range(n):
        vi = v[i]
        k1 = acc(vi)
        k2 = acc(vi + 0.5 * dt * k1)
        k3 = acc(vi + 0.5 * dt * k2)
        k4 = acc(vi + dt * k3)
        v[i + 1] = vi + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return t, v


def t95(t, v, vt):
    i = np.nonzero(v >= 0.95 * vt)[0]
    return t[i[0]] if i.size else float("nan")


# ---------------------------------------------------------------- reading
NUM = r"[-+0-9.eE]+"
VEC = re.compile(r"\((%s) (%s) (%s)\)" % (NUM, NUM, NUM))


def foam_body(path):
    s = open(path).read()
    i = s.find("// * * *")
    return s[s.index("\n", i):] if i >= 0 else s


def read_vectors(path):
    return np.array([[float(a) for a in m] for m in VEC.findall(foam_body(path))])


def read_labels(path):
    body = foam_body(path)
    m = re.search(r"(\d+)\s*\(([^)]*)\)", body, re.S)
    return np.array([int(x) for x in m.group(2).split()])


def dpm_history(case):
    """(t, list of (origId, U)) at the write times of a DPMFoam case."""
    out = []
    for d in glob.glob(os.path.join(case, "[0-9]*")):
        cloud = os.path.join(d, "lagrangian", "kinematicCloud")
        try:
            t = float(os.path.basename(d))
        except ValueError:
            continue
        if not os.path.isfile(os.path.join(cloud, "U")):
            continue
        out.append((t, read_labels(os.path.join(cloud, "origId")),
                    read_vectors(os.path.join(cloud, "U")),
                    read_vectors(os.path.join(cloud, "positions"))))
    out.sort(key=lambda x: x[0])
    return out


def dpm_log_velocity(case):
    """(t, mean vertical parcel velocity) at every time step of a DPMFoam
    run: the log's 'Linear momentum' over 'Current mass in system'."""
    t, v = [0.0], [0.0]
    cur, mass = None, None
    for line in open(os.path.join(case, "log.DPMFoam")):
        if line.startswith("Time = "):
            cur = float(line.split()[2])
        elif "Current mass in system" in line:
            mass = float(line.split("=")[1])
        elif "Linear momentum" in line and "|" not in line and cur is not None:
            m = VEC.search(line)
            if m and mass:
                t.append(cur)
                v.append(float(m.group(3)) / mass)
    return np.array(t), np.array(v)


def wall_time(case):
    try:
        return float(open(os.path.join(case, "wallTime")).read().split()[0])
    except (OSError, ValueError, IndexError):
        return float("nan")


def cpu_time(case):
    """The solver's last 'ExecutionTime' (CPU seconds) in its log."""
    val = float("nan")
    for log in glob.glob(os.path.join(case, "log.*Foam")):
        for line in open(log, errors="replace"):
            if line.startswith("ExecutionTime"):
                val = float(line.split()[2])
    return val


def timing_split(case):
    """interDemFoam's or pimpleDemFoam's 'Timing split: DEM a s, CFD b s,
    coupling c s'."""
    for log in glob.glob(os.path.join(case, "log.*DemFoam")):
        for line in open(log, errors="replace"):
            if line.startswith("Timing split"):
                return line.strip()
    return ""


def n_cells(case):
    owner = os.path.join(case, "constant", "polyMesh", "owner")
    try:
        head = open(owner, "rb").read(4000).decode("latin-1")
        m = re.search(r"nCells:\s*(\d+)", head)
        return int(m.group(1)) if m else -1
    except OSError:
        return -1


def lattice():
    pts = np.array([((i + 0.5) * LATTICE, (j + 0.5) * LATTICE,
                     Z0 + (k + 0.5) * LATTICE)
                    for k in range(NZ) for j in range(NY) for i in range(NX)])
    rng = np.random.default_rng(1)
    return pts + rng.uniform(-JITTER, JITTER, pts.shape)


# ---------------------------------------------------------------- commands
def positions(path, path_dem):
    pts = lattice()
    with open(path, "w") as f:
        f.write("FoamFile\n{\n    version 2.0;\n    format ascii;\n"
                "    class vectorField;\n    object kinematicCloudPositions;\n}\n"
                "// written by dpmCompare.py: %d positions, those of "
                "column/interDemFoam (DEM/particles.liggghts)\n\n(\n" % len(pts))
        for p in pts:
            f.write("(%.9g %.9g %.9g)\n" % tuple(p))
        f.write(")\n")
    with open(path_dem, "w") as f:
        f.write("# written by dpmCompare.py: %d particles, those of "
                "column/DPMFoam (constant/kinematicCloudPositions)\n" % len(pts))
        for p in pts:
            f.write("create_atoms 1 single %.9g %.9g %.9g units box\n" % tuple(p))


SETTLING = [  # name, label, kind
    ("settling-interDemFoam-centre", "interDemFoam, centre void fraction", "idf"),
    ("settling-interDemFoam-divided", "interDemFoam, divided void fraction", "idf"),
    ("settling-pimpleDemFoam-divided", "pimpleDemFoam (one phase), divided", "idf"),
    ("settling-DPMFoam", "DPMFoam (WenYuDrag)", "dpm"),
]
COLUMN = [  # name, label, kind, closure
    ("column-interDemFoam-Gidaspow", "interDemFoam, GidaspowDrag (Wen-Yu)", "idf", "GidaspowA"),
    ("column-interDemFoam-DiFelice", "interDemFoam, DiFeliceDrag", "idf", "DiFeliceA"),
    ("column-pimpleDemFoam-Gidaspow", "pimpleDemFoam (one phase), GidaspowDrag", "idf", "GidaspowA"),
    ("column-DPMFoam", "DPMFoam, WenYuDrag", "dpm", "WenYuB"),
]


def analyse_settling(run, plt):
    t_end = 0.25
    vt_ref = terminal("SN")
    t_ref, v_ref = ode("SN", t_end)
    t95_ref = t95(t_ref, v_ref, vt_ref)
    eps_cell = 1 - VP / DX ** 3
    vt_wy = terminal("WenYuB", eps_cell)
    t_wy, v_wy = ode("WenYuB", t_end, eps_cell)
    rows = []
    fig, (ax, axe) = plt.subplots(2, 1, figsize=(7, 7), sharex=True,
                                  gridspec_kw={"height_ratios": [2, 1]})
    ax.plot(t_ref, v_ref, "k-", lw=1.5,
            label="reference ODE, Schiller-Naumann ($v_t$ = %.4f m/s)" % vt_ref)
    ax.plot(t_wy, v_wy, color="0.6", ls=":", lw=1.2,
            label="ODE, Wen-Yu at host-cell $\\alpha$ = %.4f" % eps_cell)
    styles = {"idf": ["r-", "m--", "g-."], "dpm": ["b-"]}
    used = {"idf": 0, "dpm": 0}
    for name, label, kind in SETTLING:
        case = os.path.join(run, name)
        try:
            if kind == "idf":
                h = np.loadtxt(os.path.join(case, "particleHistory.dat"), ndmin=2)
                t, v = h[:, 0], -h[:, 2]
            else:
                t, v = dpm_log_velocity(case)
                v = -v
        except (OSError, IndexError, ValueError) as e:
            print("settling: %s not read (%s)" % (name, e))
            continue
        sty = styles[kind][used[kind]]
        used[kind] += 1
        ax.plot(t, v, sty, lw=1.2, label=label)
        vref_at = np.interp(t, t_ref, v_ref)
        ok = t > 0.01
        with np.errstate(invalid="ignore", divide="ignore"):
            err = (v - vref_at) / vref_at
        axe.plot(t[ok], 100 * err[ok], sty, lw=1.2, label=label)
        tail = t >= 0.8 * t_end
        vt = float(np.mean(v[tail]))
        rows.append((name, n_cells(case), vt, 100 * (vt - vt_ref) / vt_ref,
                     t95(t, v, vt), t95(t, v, vt_ref),
                     100 * np.max(np.abs(err[ok])),
                     wall_time(case), cpu_time(case),
                     wall_time(case) / t_end))
    ax.axhline(vt_ref, color="0.5", lw=0.7, ls="-.")
    ax.set_ylabel("settling velocity [m/s]")
    ax.set_title("1 mm, 2500 kg/m$^3$ sphere from rest in still water (cells 4 d)")
    ax.legend(fontsize=8, loc="lower right")
    ax.grid(alpha=0.3)
    axe.set_xlabel("t [s]")
    axe.set_ylabel("v / v$_{ODE}$ - 1 [%]")
    axe.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "dpmFoamSettling.png"), dpi=120)

    hdr = ("# Single particle settling in still water, d = 1 mm, rho_p = 2500, "
           "water 1000 kg/m3, 1e-3 Pa s; cells 4 mm; t_end 0.25 s, dt 1e-4 s\n"
           "# reference: RK4 ODE with Schiller-Naumann: v_t = %.5f m/s "
           "(Re_t = %.1f), t95 = %.4f s; with Wen-Yu at the host-cell "
           "alpha %.4f (DPMFoam's own law): v_t = %.5f m/s\n"
           "# v_t: mean over t >= 0.2 s; t95: first time at 95 %% of own v_t "
           "(t95ref: of the reference v_t); maxErr: max |v/v_ODE - 1| for "
           "t > 0.01 s; wall: solver wall-clock [s] on one core (another job on "
           "the machine's other core: +-30 %% between runs); cpu: the log's "
           "ExecutionTime [s]\n"
           "# case  cells  v_t[m/s]  err_vt[%%]  t95[s]  t95ref[s]  maxErr[%%]"
           "  wall[s]  cpu[s]  wall_per_simulated_s[s]\n"
           % (vt_ref, RHO_F * vt_ref * D / MU, t95_ref, eps_cell, vt_wy))
    with open(os.path.join(run, "dpmFoamSettling.dat"), "w") as f:
        f.write(hdr)
        for r in rows:
            f.write("%-30s %6d %9.5f %+7.2f %7.4f %7.4f %7.2f %8.1f %8.1f %8.1f\n" % r)
    print(hdr.rstrip())
    for r in rows:
        print("%-30s %6d %9.5f %+7.2f %7.4f %7.4f %7.2f %8.1f %8.1f %8.1f" % r)
    for name, _, kind in SETTLING:
        if kind == "idf" and timing_split(os.path.join(run, name)):
            print("# %s: %s" % (name, timing_split(os.path.join(run, name))))


def analyse_column(run, plt):
    eps = 1 - 8 * VP / DX ** 3                     # in every cell of the column
    n_part = NX * NY * NZ
    dt = 1e-4
    fig, ax = plt.subplots(figsize=(7, 5))
    rows = []
    refs = {}
    for law, vt_law in (("SN", terminal("SN")), ("DF", terminal("DiFeliceA"))):
        re_t = RHO_F * vt_law * D / MU
        n_gad = (5.1 + 0.27 * re_t ** 0.9) / (1 + 0.1 * re_t ** 0.9)
        n_rz = 4.45 * re_t ** -0.1
        refs[law] = (vt_law, re_t, n_gad, n_rz, vt_law * eps ** n_gad,
                     vt_law * eps ** n_rz)
    colours = {"GidaspowA": "r", "DiFeliceA": "m", "WenYuB": "b"}
    t_lo = 0.1
    for name, label, kind, closure in COLUMN:
        case = os.path.join(run, name)
        try:
            if kind == "idf":
                h = np.loadtxt(os.path.join(case, "columnHistory.dat"), ndmin=2)
                t, v, zmin = h[:, 0], -h[:, 1], h[:, 3]
            else:
                hist = dpm_history(case)
                lat = lattice()
                t, v, zmin = [0.0], [0.0], [Z0]
                for tt, ids, U, X in hist:
                    z0 = lat[ids, 2]
                    mid = (z0 > MID[0]) & (z0 < MID[1])
                    t.append(tt)
                    v.append(-float(np.mean(U[mid, 2])))
                    zmin.append(float(X[:, 2].min()))
                t, v, zmin = np.array(t), np.array(v), np.array(zmin)
        except (OSError, IndexError, ValueError) as e:
            print("column: %s not read (%s)" % (name, e))
            continue
        law = "DF" if closure == "DiFeliceA" else "SN"
        vt_law, re_t, n_gad, n_rz, v_gad, v_rz = refs[law]
        v_cl = hindered(closure, eps)
        c = "g" if "pimpleDemFoam" in name else colours[closure]
        ax.plot(t, v, c + ("-" if kind == "idf" else "o-"), lw=1.2, ms=3,
                label=label)
        # window: after the start-up transient, while the lowest particle is
        # more than 5 mm above the floor
        win = (t >= t_lo) & (zmin > 5e-3)
        vm = float(np.mean(v[win])) if win.any() else float("nan")
        t_hi = float(t[win][-1]) if win.any() else float("nan")
        wall = wall_time(case)
        t_sim = 0.3
        steps = t_sim / dt
        rows.append((name, n_cells(case), n_part, vm, t_lo, t_hi, vt_law, n_gad,
                     v_gad, 100 * (vm - v_gad) / v_gad, v_rz,
                     100 * (vm - v_rz) / v_rz, v_cl, 100 * (vm - v_cl) / v_cl,
                     wall, cpu_time(case), wall / t_sim,
                     1e6 * wall / (n_part * steps)))
        ax.axhline(v_cl, color=c, lw=0.8, ls=":")
    for law, ls in (("SN", "--"), ("DF", "-.")):
        vt_law, re_t, n_gad, n_rz, v_gad, v_rz = refs[law]
        ax.axhline(v_gad, color="k", lw=1.0, ls=ls,
                   label="Richardson-Zaki, $v_t$ %s %.4f, n = %.2f (Garside-Al-Dibouni)"
                   % ("Schiller-Naumann" if law == "SN" else "Di Felice", vt_law, n_gad))
    ax.set_xlabel("t [s]")
    ax.set_ylabel("mean settling velocity, middle half [m/s]")
    ax.set_ylim(0, 0.16)
    ax.set_title("2880 particles (1 mm, 2500 kg/m$^3$) in water, $\\varepsilon$ = %.4f;"
                 " dotted: each closure's own prediction" % eps, fontsize=9)
    ax.legend(fontsize=7, loc="lower right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "dpmFoamColumn.png"), dpi=120)

    hdr = ("# Settling column: %d particles, d = 1 mm, rho_p = 2500 kg/m3, water; "
           "eps = %.4f (2 mm lattice, +-0.4 mm random offsets; cells 4 mm); t_end 0.3 s, CFD dt 1e-4 s "
           "(interDemFoam: DEM dt 1e-5 s)\n"
           "# v_mean: mean settling velocity of the middle half (initial z 50..70 mm)"
           " over [t_lo, t_hi]; v_t: single-particle terminal velocity of the "
           "code's drag law (eps = 1); RZ: v_t eps^n, n of Garside-Al-Dibouni "
           "(n_GAD) and of Richardson-Zaki 4.45 Re_t^-0.1; closure: the hindered "
           "velocity the drag closure itself implies\n"
           "# wall: solver wall-clock [s] on one core (+-30 %% between runs: another "
           "job on the other core); cpu: the log's ExecutionTime [s]; "
           "us/(particle CFD step) = wall / (particles x 3000 CFD steps)\n"
           "# case  cells  particles  v_mean[m/s]  t_lo  t_hi  v_t  n_GAD  v_RZ_GAD"
           "  err_GAD[%%]  v_RZ_RZ  err_RZ[%%]  v_closure  err_closure[%%]  wall[s]  cpu[s]"
           "  wall_per_simulated_s[s]  us_per_particle_step\n" % (n_part, eps))
    fmt = ("%-30s %5d %5d %8.5f %5.3f %5.3f %8.5f %5.2f %8.5f %+7.2f %8.5f %+7.2f"
           " %8.5f %+7.2f %8.1f %8.1f %8.1f %7.2f")
    with open(os.path.join(run, "dpmFoamColumn.dat"), "w") as f:
        f.write(hdr)
        for r in rows:
            f.write(fmt % r + "\n")
    print(hdr.rstrip())
    for r in rows:
        print(fmt % r)
    for name, _, kind, _ in COLUMN:
        if kind == "idf" and timing_split(os.path.join(run, name)):
            print("# %s: %s" % (name, timing_split(os.path.join(run, name))))


def main(argv):
    if len(argv) == 4 and argv[1] == "positions":
        positions(argv[2], argv[3])
        return 0
    if len(argv) == 3 and argv[1] == "analyse":
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        analyse_settling(argv[2], plt)
        print()
        analyse_column(argv[2], plt)
        return 0
    print(__doc__)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
