#!/usr/bin/env python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Packed bed and fluidization against Ergun (1952) and Wen & Yu (1966).

  plotPackedBed.py fixed RUN...   pressure gradient in the bed of each fixed-
                                  bed run (one per drag law) vs Ergun:
                                  pressureDrop.dat, pressureDrop.png
  plotPackedBed.py fluidize RUN   pressure drop and bed height along the
                                  velocity ramp, minimum fluidization velocity
                                  vs Wen-Yu: fluidization.dat, .png

Options: --z1 --z2 (measuring planes in the bed, m; default 0.010, 0.030),
--d --rhoP --rhoF --mu (bead and water), --check TOL (exit 1 when an error
exceeds TOL, a fraction), --noPlot.
Reads the ASCII fields of the run's write times (p_rgh, voidfraction, C),
constant/inletVelocity and postProcessing/inletPressure.
"""
import argparse, math, os, re, sys

G = 9.81


def read_internal(path, vector=False):
    s = open(path).read()
    kind = 'vector' if vector else 'scalar'
    m = re.search(r'internalField\s+nonuniform\s+List<%s>\s*(\d+)\s*\(' % kind, s)
    if not m:
        m = re.search(r'internalField\s+uniform\s+(\S+);', s)
        raise SystemExit('%s: uniform field, expected one value per cell' % path)
    n = int(m.group(1))
    body = s[m.end():]
    if vector:
        vals = re.findall(r'\(([^()]*)\)', body)[:n]
        return [tuple(float(x) for x in v.split()) for v in vals]
    return [float(x) for x in body.split(')')[0].split()[:n]]


def read_table(path):
    """OpenFOAM tableFile of (t (ux uy uz)) rows -> [(t, uz)]"""
    s = open(path).read()
    rows = re.findall(r'\(\s*([-+0-9.eE]+)\s*\(\s*\S+\s+\S+\s+([-+0-9.eE]+)\s*\)\s*\)', s)
    return [(float(t), float(u)) for t, u in rows]


def interp(table, t):
    if t <= table[0][0]:
        return table[0][1]
    for (t0, u0), (t1, u1) in zip(table, table[1:]):
        if t0 <= t <= t1:
            return u0 + (u1 - u0)*(t - t0)/(t1 - t0) if t1 > t0 else u1
    return table[-1][1]


def time_dirs(case):
    out = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if t > 0 and os.path.isfile(os.path.join(case, name, 'p_rgh')):
            out.append((t, name))
    return sorted(out)


def ergun(eps, U, a):
    """-dp/dz [Pa/m] of Ergun (1952) at superficial velocity U"""
    return (150*a.mu*(1 - eps)**2*U/(eps**3*a.d**2)
            + 1.75*a.rhoF*(1 - eps)*U**2/(eps**3*a.d))


def wen_yu_umf(a):
    Ar = a.rhoF*(a.rhoP - a.rhoF)*G*a.d**3/a.mu**2
    Re = math.sqrt(33.7**2 + 0.0408*Ar) - 33.7
    return Re*a.mu/(a.rhoF*a.d)


def bed_slab(case, name, a, centres):
    """Pressure gradient between the layers at z1 and z2 and the mean eps
    between them (trapezoidal weights, as the pressure difference sees it)"""
    p = read_internal(os.path.join(case, name, 'p_rgh'))
    eps = read_internal(os.path.join(case, name, 'voidfraction'))
    layers = {}
    for i, c in enumerate(centres):
        z = round(c[2], 9)
        layers.setdefault(z, []).append(i)
    zs = sorted(layers)
    lo = min(zs, key=lambda z: abs(z - a.z1))
    hi = min(zs, key=lambda z: abs(z - a.z2))
    mean = lambda f, z: sum(f[i] for i in layers[z])/len(layers[z])
    dpdz = (mean(p, lo) - mean(p, hi))/(hi - lo)
    inside = [z for z in zs if lo <= z <= hi]
    w = [0.5 if z in (lo, hi) else 1.0 for z in inside]
    epsm = sum(wi*mean(eps, z) for wi, z in zip(w, inside))/sum(w)
    return dpdz, epsm, lo, hi


def solid_volume(case, name):
    eps = read_internal(os.path.join(case, name, 'voidfraction'))
    V = read_internal(os.path.join(case, name, 'V')) \
        if os.path.isfile(os.path.join(case, name, 'V')) else None
    return eps, V


def fixed(a):
    rows = []
    for run in a.runs:
        law = os.path.basename(os.path.normpath(run)).split('.', 1)[-1]
        centres = read_internal(os.path.join(run, '0', 'C'), vector=True)
        table = read_table(os.path.join(run, 'constant', 'inletVelocity'))
        for t, name in time_dirs(run):
            U = interp(table, t)
            dpdz, eps, lo, hi = bed_slab(run, name, a, centres)
            ref = ergun(eps, U, a)
            rows.append((law, U, a.rhoF*U*a.d/a.mu, eps, dpdz, ref,
                         dpdz/ref - 1))
    with open('pressureDrop.dat', 'w') as f:
        f.write('# bed between z = %g and %g m; Re = rho U d/mu (superficial)\n'
                % (a.z1, a.z2))
        f.write('# law U[m/s] Re eps dpdz[Pa/m] ergun[Pa/m] error\n')
        for r in rows:
            f.write('%s %.5g %.4g %.4f %.6g %.6g %+.4f\n' % r)
    print('Packed bed, pressure gradient between z = %g and %g m vs Ergun:'
          % (a.z1, a.z2))
    print('  %-20s %9s %6s %7s %11s %11s %8s'
          % ('law', 'U [m/s]', 'Re', 'eps', '-dp/dz', 'Ergun', 'error'))
    for r in rows:
        print('  %-20s %9.4f %6.1f %7.4f %11.1f %11.1f %+7.2f %%'
              % (r[0], r[1], r[2], r[3], r[4], r[5], 100*r[6]))
    worst = {}
    for r in rows:
        worst[r[0]] = max(worst.get(r[0], 0), abs(r[6]))
    for law, e in worst.items():
        print('  %-20s largest |error| %.2f %%' % (law, 100*e))

    if not a.noPlot:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.4, 4.6))
        laws = list(dict.fromkeys(r[0] for r in rows))
        eps = sum(r[3] for r in rows)/len(rows)
        Umax = max(r[1] for r in rows)*1.1
        Us = [Umax*i/100 for i in range(101)]
        ax.plot(Us, [ergun(eps, u, a)/1e3 for u in Us], 'k-',
                label='Ergun, eps = %.3f' % eps)
        for law, mk in zip(laws, 'osD^v<>'):
            sel = [r for r in rows if r[0] == law]
            ax.plot([r[1] for r in sel], [r[4]/1e3 for r in sel], mk,
                    mfc='none', ms=8, label=law)
        ax.set_xlabel('superficial velocity U [m/s]')
        ax.set_ylabel('-dp/dz [kPa/m]')
        ax.set_title('Fixed bed, d = %g mm glass in water' % (a.d*1e3))
        ax.legend()
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig('pressureDrop.png', dpi=120)
    if a.check is not None:
        bad = [law for law, e in worst.items() if e > a.check]
        if bad:
            print('FAIL: error above %.0f %% for %s' % (100*a.check, ' '.join(bad)))
            sys.exit(1)
        print('PASS: every law within %.0f %% of Ergun' % (100*a.check))


def fluidize(a):
    run = a.runs[0]
    table = read_table(os.path.join(run, 'constant', 'inletVelocity'))
    # Buoyant weight per area from the particle volume the CFD holds
    t0 = time_dirs(run)[0][1]
    eps = read_internal(os.path.join(run, t0, 'voidfraction'))
    V = read_internal(os.path.join(run, '0', 'V'))
    centres = read_internal(os.path.join(run, '0', 'C'), vector=True)
    Vs = sum((1 - e)*v for e, v in zip(eps, V))
    zb = min(c[2] for c in centres)
    area = sum(v for v, c in zip(V, centres) if abs(c[2] - zb) < 1e-9) \
        / (2*zb)
    W = Vs*(a.rhoP - a.rhoF)*G/area

    pfile = None
    for root, _, files in os.walk(os.path.join(run, 'postProcessing', 'inletPressure')):
        for f in files:
            if f.endswith('.dat'):
                pfile = os.path.join(root, f)
    data = []
    for line in open(pfile):
        if line.startswith('#') or not line.strip():
            continue
        t, p = (float(x) for x in line.split()[:2])
        data.append((t, interp(table, t), p))
    height = []
    hfile = os.path.join(run, 'DEM', 'bedHeight.dat')
    for line in open(hfile):
        if line.startswith('#') or not line.strip():
            continue
        t, zcm, ztop = (float(x) for x in line.split()[:3])
        height.append((t, interp(table, t), zcm))

    # The pressure at the plate jumps from step to step (each DEM step
    # changes eps, and d(eps)/dt is felt at once in incompressible flow):
    # average it over velocity bins of 1/40 of the ramp
    Uend = table[-1][1]
    nBins = 40
    sums = [0.0]*nBins
    counts = [0]*nBins
    for _, u, p in data:
        b = int(u/Uend*nBins)
        if 0 <= b < nBins:
            sums[b] += p
            counts[b] += 1
    binned = [((b + 0.5)*Uend/nBins, sums[b]/counts[b])
              for b in range(nBins) if counts[b]]
    # plateau: the last quarter of the ramp
    tail = [p for u, p in binned if u > 0.75*Uend]
    plateau = sum(tail)/len(tail)
    # Fixed-bed branch dp = a U + b U^2 through the bins below 0.6 of the
    # plateau; U_mf where it meets the plateau (Kunii & Levenspiel's
    # construction)
    pts = [(u, p) for u, p in binned if 0 < p < 0.6*plateau]
    S11 = sum(u**2 for u, _ in pts); S12 = sum(u**3 for u, _ in pts)
    S22 = sum(u**4 for u, _ in pts)
    b1 = sum(u*p for u, p in pts); b2 = sum(u*u*p for u, p in pts)
    det = S11*S22 - S12**2
    ca = (b1*S22 - b2*S12)/det
    cb = (S11*b2 - S12*b1)/det
    if abs(cb) > 1e-12*abs(ca):
        disc = ca**2 + 4*cb*plateau
        Umf = (-ca + math.sqrt(disc))/(2*cb)
    else:
        Umf = plateau/ca
    Uwy = wen_yu_umf(a)
    z0 = height[0][2]
    # Onset of expansion, a second reading of U_mf from the particles: where
    # the line through the expanding bed's rise (last quarter of the ramp)
    # meets the line through the fixed bed's creep (below U_mf/2, Wen-Yu)
    def line(pts):
        n = len(pts)
        mx = sum(x for x, _ in pts)/n
        my = sum(y for _, y in pts)/n
        sxx = sum((x - mx)**2 for x, _ in pts)
        k = sum((x - mx)*(y - my) for x, y in pts)/sxx
        return k, my - k*mx
    z0 = height[0][2]
    k1, c1 = line([(u, z - z0) for _, u, z in height if 0.1*Uwy < u < 0.5*Uwy])
    k2, c2 = line([(u, z - z0) for _, u, z in height if u > 0.75*Uend])
    Uexp = (c1 - c2)/(k2 - k1)
    with open('fluidization.dat', 'w') as f:
        f.write('# U[m/s] dp[Pa] dp/W (bin means)\n')
        for u, p in binned:
            f.write('%.5g %.6g %.5f\n' % (u, p, p/W))
    err = Umf/Uwy - 1
    print('Fluidization (ramp to %.3f m/s):' % table[-1][1])
    print('  bed buoyant weight per area W = %.2f Pa; plateau dp = %.2f Pa '
          '(%.3f W)' % (W, plateau, plateau/W))
    print('  fixed-bed branch dp = %.4g U + %.4g U^2 (Pa, m/s)' % (ca, cb))
    print('  U_mf measured %.5f m/s, Wen-Yu %.5f m/s: error %+.1f %%'
          % (Umf, Uwy, 100*err))
    print('  bed starts to expand at U = %.5f m/s (%+.1f %% of Wen-Yu)'
          % (Uexp, 100*(Uexp/Uwy - 1)))
    print('  bed centre of mass rose %.2f mm (%.4f -> %.4f m)'
          % (1e3*(height[-1][2] - z0), z0, height[-1][2]))
    with open('fluidization.summary', 'w') as f:
        f.write('W %.6g\nplateau %.6g\nUmf %.6g\nUmfWenYu %.6g\nerror %.4f\n'
                'Uexpansion %.6g\n' % (W, plateau, Umf, Uwy, err, Uexp))
    if not a.noPlot:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, (ax, ax2) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True)
        # every CFD step as it is (not clipped): the plate pressure's own
        # noise, next to the bin means
        steps = [p/W for _, _, p in data]
        jumps = [abs(b - a) for a, b in zip(steps, steps[1:])]
        meanJump = sum(jumps)/max(len(jumps), 1)
        # the solver that ran the case (its log's name)
        solver = 'pimpleDemFoam' \
            if os.path.isfile(os.path.join(run, 'log.pimpleDemFoam')) \
            else 'interDemFoam'
        ax.plot([u for _, u, _ in data], steps, '-', color='0.55', lw=0.5,
                label='every CFD step (mean step-to-step change %.2g W)' % meanJump)
        ax.plot([u for u, _ in binned], [p/W for _, p in binned], 'o-',
                ms=3, label='%s, bin means' % solver)
        Us = [Umf*i/50 for i in range(51)]
        ax.plot(Us, [(ca*u + cb*u*u)/W for u in Us], 'k--', lw=1,
                label='fixed-bed fit')
        ax.axhline(1, color='k', lw=0.8)
        ax.axvline(Uwy, color='r', lw=1, label='Wen-Yu U_mf = %.4f' % Uwy)
        ax.axvline(Umf, color='b', lw=1, ls=':', label='measured U_mf = %.4f' % Umf)
        ax.set_ylabel('dp / (bed weight per area)')
        ax.set_ylim(min(0, 1.05*min(steps)), max(1.3, 1.05*max(steps)))
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        ax2.plot([u for _, u, _ in height], [1e3*(z - z0) for _, _, z in height],
                 label='bed released, ramp %.3f m/s in %g s' % (Uend, table[-1][0]))
        ax2.legend(fontsize=8)
        ax2.axvline(Uwy, color='r', lw=1)
        ax2.axvline(Umf, color='b', lw=1, ls=':')
        ax2.set_xlabel('superficial velocity U [m/s]')
        ax2.set_ylabel('rise of the bed centre [mm]')
        ax2.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig('fluidization.png', dpi=120)
    if a.check is not None:
        if abs(err) > a.check:
            print('FAIL: U_mf off Wen-Yu by more than %.0f %%' % (100*a.check))
            sys.exit(1)
        print('PASS: U_mf within %.0f %% of Wen-Yu' % (100*a.check))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('mode', choices=['fixed', 'fluidize'])
    ap.add_argument('runs', nargs='+')
    ap.add_argument('--z1', type=float, default=0.010)
    ap.add_argument('--z2', type=float, default=0.030)
    ap.add_argument('--d', type=float, default=0.002)
    ap.add_argument('--rhoP', type=float, default=2500.0)
    ap.add_argument('--rhoF', type=float, default=1000.0)
    ap.add_argument('--mu', type=float, default=1e-3)
    ap.add_argument('--check', type=float, default=None)
    ap.add_argument('--noPlot', action='store_true')
    a = ap.parse_args()
    fixed(a) if a.mode == 'fixed' else fluidize(a)


if __name__ == '__main__':
    main()
