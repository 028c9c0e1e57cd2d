#!/usr/bin/python3
# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Bedload flux and bed shear stress of the bedload tutorial's runs.

  bedloadAnalysis.py run <run>              <run>/bedload.summary (+ print)
  bedloadAnalysis.py collect <out> <runs>   <out>.dat (theta qstar ...) and
                                            <out>.png (q* against theta with
                                            Meyer-Peter-Mueller, Wong-Parker)
  bedloadAnalysis.py chart <png> <label>=<table.dat> ...
                                            q* against theta of several
                                            tables (sensitivity runs)
  bedloadAnalysis.py profile <run>          where the fluid force acts:
                                            the share of F_x on the grains
                                            by height of their centres
                                            (dumps of the averaging window)
  bedloadAnalysis.py flagship              the estimate of theta in the
                                            flagship's overtopping (docs/
                                            erosion.md)
  bedloadAnalysis.py nearBed <run>          the turbulence the bed's grains
                                            see (k-omega runs): per cell
                                            layer, k, k/u*^2, the grains'
                                            fluctuation intensity and life
  bedloadAnalysis.py mobile <run> ...       why the flux is what it is:
                                            how many grains move and how
                                            fast, against the fluid in the
                                            bed's surface layer, Lajeunesse
                                            et al.'s grain velocity and the
                                            number of movers Wong-Parker
                                            needs
  bedloadAnalysis.py mobileChart <png> <label>=<run prefix> ...
                                            the same against theta for
                                            sweeps (runs <prefix>.theta.*)
  bedloadAnalysis.py fractions <run> ...    which grains move on a graded
                                            bed (Allrun -grading): each
                                            size class's share of the bed,
                                            of its surface and of the
                                            flux, against Wilcock & Crowe
                                            (2003)
  bedloadAnalysis.py fractionsChart <png> <label>=<run>,<run>... ...
                                            the fine class's share of the
                                            flux and the mobility ratio
                                            against theta, beside Wilcock
                                            & Crowe's
  bedloadAnalysis.py onsetMap <out> <model>=<table.dat> ...
                                            the measured onsets checkDemScene
                                            reads (etc/sceneMaps/
                                            bedloadOnset.dat)
  options: --noPlot (collect: table only)

A run's records (Allrun, DEM/in.bedload, system/controlDict):
  DEM/flux.dat           t, q_s (sum of V_p u_p,x over the mobile grains /
                         (lx ly), m2/s), F_x on all grains, on the mobile
                         ones (N), mobile grains faster than 0.05 m/s
  postProcessing/flowVelocity/<t>/volFieldValue.dat (one folder per start)
                         t, mean U and alpha of the forced water layer
Averaging window: the second half of the run, [T/2, T]; after a
mobilised start (Allrun -mobilise: mobiliseTime t_m in caseSettings), the
second half of the part at theta, [t_m + (T - t_m)/2, T]. Statistically
steady when the water's mean velocity changes by less than 5 % across it
and the fluid force on the grains is within 10 % of rho g S h lx ly.

  theta      = tau_b / ((rho_s - rho) g d), tau_b = rho g S h (imposed)
  thetaGrain = <F_x> / (lx ly) / ((rho_s - rho) g d) (measured)
  qstar      = <q_s> / sqrt((s - 1) g d^3), s = rho_s / rho
Transport (sustained): q* > 1e-3 in each half of the window (q* = 1e-3 is
Meyer-Peter-Mueller at theta = 0.0495, 5 % above its threshold 0.047).
"""
import math
import os
import re
import sys

RHO, RHOS, G, D = 1000.0, 2650.0, 9.81, 0.01
S1 = RHOS/RHO - 1.0
QREF = math.sqrt(S1*G*D**3)          # m2/s, for d = D
TAUREF = (RHOS - RHO)*G*D            # Pa, for d = D
QMIN = 1e-3                          # sustained-transport threshold on q*


def mpm(theta):
    return 8.0*max(theta - 0.047, 0.0)**1.5


def wongParker(theta):
    return 3.97*max(theta - 0.0495, 0.0)**1.5


def settings(run):
    s = {}
    with open(os.path.join(run, 'system', 'caseSettings')) as f:
        for line in f:
            line = line.split('//')[0].strip()
            if line.endswith(';') and len(line.split()) == 2:
                k, v = line[:-1].split()
                try:
                    s[k] = float(v)
                except ValueError:
                    pass
    for k in ('theta', 'forcing', 'depth', 'lx', 'ly'):
        if k not in s:
            sys.exit('%s: no %s in system/caseSettings' % (run, k))
    # the diameter theta and q* refer to (Allrun -grading: the bed's
    # geometric mean); runs written before the option: 10 mm grains only
    s.setdefault('dRef', D)
    return s


def monodisperse(run, s):
    """Stop where a command assumes the default bed of 10 mm grains."""
    if abs(s['dRef'] - D) > 1e-9:
        sys.exit('%s: a graded bed (dRef %g m); this command is for the '
                 'default bed of 10 mm grains (use fractions)'
                 % (run, s['dRef']))


def table(path, ncol):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            w = line.replace('(', ' ').replace(')', ' ').split()
            try:
                rows.append([float(x) for x in w[:ncol]])
            except ValueError:
                continue
    return [r for r in rows if len(r) == ncol]


def mean(v):
    return sum(v)/len(v) if v else float('nan')


def window(s, T):
    """The averaging window [t0, T] and the time splitting it in halves:
    the second half of the run at theta (after mobiliseTime, if any)."""
    tm = s.get('mobiliseTime', 0.0)
    if not 0 <= tm < T:
        sys.exit('mobiliseTime %g outside the run [0, %g]' % (tm, T))
    return tm + 0.5*(T - tm), tm + 0.75*(T - tm)


def flowVelocity(run):
    """t, mean U and alpha of the forced water layer, from every start
    time's postProcessing/flowVelocity/<t>/volFieldValue.dat (a restarted
    run writes a folder per start)."""
    base = os.path.join(run, 'postProcessing', 'flowVelocity')
    rows = []
    for t in sorted(os.listdir(base), key=float):
        rows += [r for r in table(os.path.join(base, t,
                                               'volFieldValue.dat'), 5)
                 if not rows or r[0] > rows[-1][0]]
    return rows


def fluxWindow(run):
    """A run's settings, its DEM/flux.dat rows (at least 20), the end of
    the run T, the averaging window's start t0 and middle tHalf, and the
    rows in the window."""
    s = settings(run)
    flux = table(os.path.join(run, 'DEM', 'flux.dat'), 5)
    if len(flux) < 20:
        sys.exit('%s: DEM/flux.dat has %d rows' % (run, len(flux)))
    T = flux[-1][0]
    t0, tHalf = window(s, T)
    return s, flux, T, t0, tHalf, [r for r in flux if r[0] >= t0]


def windowDumps(run, t0, withTime=False):
    """The grain dumps post/grains.<step>.txt from t0 on (in step order):
    per dump, its 'ITEM: ATOMS' header's words and its atom lines' words
    (withTime: its time first, s); dumps without that header are left
    out."""
    post = os.path.join(run, 'post')
    files = sorted((int(f.split('.')[1]), f) for f in os.listdir(post)
                   if f.startswith('grains.') and f.endswith('.txt'))
    for step, f in files:
        if step*1e-4 < t0 - 1e-9:
            continue
        with open(os.path.join(post, f)) as fh:
            lines = fh.readlines()
        i = [k for k, l in enumerate(lines) if l.startswith('ITEM: ATOMS')]
        if i:
            words = (lines[i[0]].split(), [l.split() for l in lines[i[0] + 1:]])
            yield ((step*1e-4,) + words) if withTime else words


def layerMeans(values, nxy):
    """Per horizontal cell layer (nxy cells each, in the blockMesh order of
    the channel) the mean of a cell list."""
    return [mean(values[j*nxy:(j + 1)*nxy]) for j in range(len(values)//nxy)]


def analyse(run):
    s, flux, T, t0, tHalf, win = fluxWindow(run)
    area = s['lx']*s['ly']
    qRef = math.sqrt(S1*G*s['dRef']**3)
    tauRef = (RHOS - RHO)*G*s['dRef']
    half1 = [r for r in win if r[0] < tHalf]
    half2 = [r for r in win if r[0] >= tHalf]
    qs = mean([r[1] for r in win])
    # standard error from 5 block means (the flux is correlated in time)
    nb = 5
    blocks = [mean([r[1] for r in win[i*len(win)//nb:(i + 1)*len(win)//nb]])
              for i in range(nb)]
    qsErr = math.sqrt(sum((b - qs)**2 for b in blocks)/(nb*(nb - 1)))
    q1 = mean([r[1] for r in half1])/qRef
    q2 = mean([r[1] for r in half2])/qRef
    Fx = mean([r[2] for r in win])
    nMoving = mean([r[4] for r in win])
    tauB = s['forcing']*s['depth']
    vel = flowVelocity(run)
    uw = [r for r in vel if r[0] >= t0]
    U = mean([r[1] for r in uw])
    n = max(len(uw)//10, 1)
    U1, U2 = mean([r[1] for r in uw[:n]]), mean([r[1] for r in uw[-n:]])
    out = {
        'theta': s['theta'],
        'qstar': qs/qRef,
        'qstarErr': qsErr/qRef,
        'qstarHalf1': q1,
        'qstarHalf2': q2,
        'transport': int(q1 > QMIN and q2 > QMIN),
        'qstarMPM': mpm(s['theta']),
        'qstarWongParker': wongParker(s['theta']),
        'tauB': tauB,
        'slope': s['forcing']/(RHO*G),
        'thetaGrain': Fx/area/tauRef,
        'forceRatio': Fx/area/tauB,
        'U': U,
        'Udrift': (U2 - U1)/U if U else float('nan'),
        'UoverUstar': U/math.sqrt(tauB/RHO),
        'nMoving': nMoving,
        'windowStart': t0,
        'windowEnd': T,
        'mobiliseTheta': s.get('mobiliseTheta', 0.0),
        'mobiliseTime': s.get('mobiliseTime', 0.0),
        'dRef': s['dRef'],
    }
    out['steady'] = int(abs(out['Udrift']) < 0.05
                        and abs(out['forceRatio'] - 1) < 0.1)
    wt = os.path.join(run, 'wallTime')
    if os.path.exists(wt):
        out['wallTime'] = float(open(wt).read().split()[1])
    with open(os.path.join(run, 'bedload.summary'), 'w') as f:
        for k, v in out.items():
            f.write('%-16s %.6g\n' % (k, v))
    return out


def readSummary(run):
    out = {'mobiliseTheta': 0.0, 'mobiliseTime': 0.0}  # runs from before
    #                                                    the option: at rest
    with open(os.path.join(run, 'bedload.summary')) as f:
        for line in f:
            k, v = line.split()
            out[k] = float(v)
    out['run'] = run
    return out


def modelLabel(run):
    """A run's model in a few words, for a chart: its turbulence model
    (constant/turbulenceProperties; laminar without one) and its cell size
    over the reference diameter."""
    model = 'laminar'
    path = os.path.join(run, 'constant', 'turbulenceProperties')
    if os.path.exists(path):
        words = open(path).read().replace(';', ' ').split()
        for key in ('RASModel', 'LESModel'):
            if key in words:
                model = words[words.index(key) + 1]
    s = settings(run)
    cells = ''
    if 'nx' in s and s['nx'] > 0:
        cells = ', cells %.3g d' % (s['lx']/s['nx']/s['dRef'])
    return model + cells


def collect(outName, runs, plot=True):
    rows = []
    for run in runs:
        if not os.path.exists(os.path.join(run, 'bedload.summary')):
            print('collect: %s has no bedload.summary (not finished?): '
                  'left out' % run)
            continue
        rows.append(readSummary(run))
    if not rows:
        sys.exit('collect: no runs with a bedload.summary')
    rows.sort(key=lambda r: r['theta'])
    # onset: the first theta from which every run transports
    # (a run that is not statistically steady measures no onset)
    onset = None
    for i, r in enumerate(rows):
        if all(x['transport'] and x['steady'] for x in rows[i:]):
            onset = r['theta']
            break
    unsteady = ['%g' % r['theta'] for r in rows if not r['steady']]
    os.makedirs(os.path.dirname(outName) or '.', exist_ok=True)
    cols = ['theta', 'qstar', 'qstarErr', 'transport', 'qstarMPM',
            'qstarWongParker', 'thetaGrain', 'U', 'UoverUstar', 'Udrift',
            'nMoving', 'steady', 'windowStart', 'windowEnd', 'wallTime',
            'mobiliseTheta', 'mobiliseTime']
    with open(outName + '.dat', 'w') as f:
        f.write('# Bedload flux against the Shields number '
                '(tutorials/interDemFoam/bedload, bedloadAnalysis.py)\n')
        f.write('# theta: imposed, tau_b = rho g S h; qstar = <q_s>/sqrt((s-1) g d^3) '
                'over the window [windowStart, windowEnd] s; qstarErr: standard '
                'error (5 blocks)\n')
        f.write('# transport: q* > 1e-3 in both halves of the window; '
                'thetaGrain: measured fluid force on the grains per bed area / '
                '((rho_s - rho) g d); U: mean water velocity (m/s); Udrift: its '
                'relative change across the window; nMoving: mobile grains '
                'faster than 0.05 m/s; steady: |Udrift| < 5 %% and thetaGrain '
                'within 10 %% of theta; wallTime: s; mobiliseTheta, '
                'mobiliseTime: the bed first driven at that theta for that '
                'time (s; Allrun -mobilise; 0: started at rest)\n')
        f.write('# onset theta_c (first theta from which every run '
                'transports, steady): %s\n' % (('%g' % onset) if onset else 'none'))
        if unsteady:
            f.write('# NOT statistically steady (no valid point): theta %s\n'
                    % ' '.join(unsteady))
        f.write('# ' + ' '.join(cols) + '\n')
        for r in rows:
            f.write(' '.join('%.5g' % r.get(c, float('nan')) for c in cols)
                    + '\n')
    print('%-8s %-10s %-9s %-9s %-9s %-10s %-6s %-6s %s' % (
        'theta', 'qstar', '+-', 'MPM', 'WP', 'thetaGrain', 'U', 'U/u*',
        'transport'))
    for r in rows:
        print('%-8.4g %-10.4g %-9.2g %-9.4g %-9.4g %-10.4g %-6.3g %-6.3g %d'
              % (r['theta'], r['qstar'], r['qstarErr'], r['qstarMPM'],
                 r['qstarWongParker'], r['thetaGrain'], r['U'],
                 r['UoverUstar'], r['transport']))
    print('onset theta_c = %s (criterion: q* > %g in both halves of the '
          'window)' % (('%g' % onset) if onset else 'none', QMIN))
    if unsteady:
        print('NOT statistically steady (no valid point): theta %s'
              % ' '.join(unsteady))
    if not plot:
        return
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    th = [0.047 + i*0.001 for i in range(0, 1000)]
    ax.plot(th, [mpm(t) for t in th], 'k-',
            label=r'Meyer-Peter-M\"uller $8(\theta-0.047)^{1.5}$'
            .replace(r'\"u', 'ü'))
    ax.fill_between(th, [0.5*mpm(t) for t in th], [2*mpm(t) for t in th],
                    color='0.85', label='MPM x/÷ 2')
    ax.plot(th, [wongParker(t) for t in th], 'k--',
            label=r'Wong-Parker $3.97(\theta-0.0495)^{1.5}$')
    ax.axvspan(0.03, 0.06, color='tab:blue', alpha=0.12,
               label=r'$\theta_c$ of coarse grains 0.03-0.06')
    floor = 1e-4
    pos = [r for r in rows if r['qstar'] > floor]
    zero = [r for r in rows if r['qstar'] <= floor]
    ax.errorbar([r['theta'] for r in pos], [r['qstar'] for r in pos],
                yerr=[r['qstarErr'] for r in pos], fmt='o', color='tab:red',
                label='interDemFoam (%s)' % modelLabel(rows[0]['run']))
    if zero:
        ax.plot([r['theta'] for r in zero], [floor*1.3]*len(zero), 'v',
                color='tab:red', mfc='none',
                label=r'interDemFoam: no transport ($q^* < 10^{-4}$)')
    if onset:
        ax.axvline(onset, color='tab:red', ls=':', label=r'measured onset')
        below = [r['theta'] for r in rows if r['theta'] < onset]
        if below:
            # MPM's excess-stress law with this model's own threshold (the
            # middle between the last theta without and the first with
            # transport)
            tc = 0.5*(below[-1] + onset)
            ts = [tc + i*0.002 for i in range(0, 500)]
            ax.plot(ts, [8*(t - tc)**1.5 for t in ts], ':', color='0.3',
                    label=r'$8(\theta-%.3g)^{1.5}$ (MPM with this '
                    r'$\theta_c$)' % tc)
    ax.set_yscale('log')
    ax.set_ylim(floor, 10)
    ax.set_xlim(0, max(0.35, 1.05*rows[-1]['theta']))
    ax.set_xlabel(r'Shields number $\theta = \tau_b/((\rho_s-\rho) g d)$')
    ax.set_ylabel(r'$q^* = q_s/\sqrt{(s-1) g d^3}$')
    dRef = rows[0].get('dRef', D)          # summaries from before -grading: 10 mm
    ax.set_title('Bedload, d = %s: %s' % (
        '10 mm' if abs(dRef - D) < 1e-9 else
        '%.3g mm (geometric mean of the grading)' % (1000*dRef),
        os.path.basename(outName)))
    ax.legend(fontsize=7, loc='lower right')
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(outName + '.png', dpi=120)
    print('wrote %s.dat, %s.png' % (outName, outName))


def chart(outPng, tables):
    """q* against theta of several tables (label=path.dat), with MPM and
    Wong-Parker: the sensitivity runs of docs/erosion.md."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    th = [0.047 + i*0.001 for i in range(0, 1000)]
    ax.plot(th, [mpm(t) for t in th], 'k-', label='Meyer-Peter-Müller')
    ax.fill_between(th, [0.5*mpm(t) for t in th], [2*mpm(t) for t in th],
                    color='0.85', label='MPM x/÷ 2')
    ax.plot(th, [wongParker(t) for t in th], 'k--', label='Wong-Parker')
    ax.axvspan(0.03, 0.06, color='tab:blue', alpha=0.12,
               label=r'$\theta_c$ 0.03-0.06')
    floor = 1e-4
    markers = 'osD^vP'
    for k, spec in enumerate(tables):
        label, path = spec.rsplit('=', 1)
        rows = table(path, 2)
        m = markers[k % len(markers)]
        pos = [r for r in rows if r[1] > floor]
        zero = [r for r in rows if r[1] <= floor]
        line, = ax.plot([r[0] for r in pos], [r[1] for r in pos], m + '-',
                        label=label)
        if zero:
            ax.plot([r[0] for r in zero], [floor*1.3]*len(zero), m,
                    mfc='none', color=line.get_color())
    ax.set_yscale('log')
    ax.set_ylim(floor, 10)
    ax.set_xlim(0, 0.85)
    ax.set_xlabel(r'Shields number $\theta$')
    ax.set_ylabel(r'$q^* = q_s/\sqrt{(s-1) g d^3}$')
    ax.set_title(r'Bedload: what moves the onset (open: $q^* < 10^{-4}$)')
    ax.legend(fontsize=7, loc='lower right')
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(outPng, dpi=120)
    print('wrote %s' % outPng)


def profile(run):
    """Share of the fluid force along x by the height of the grain centres,
    from the dumps post/grains.*.txt in the averaging window (columns id x
    y z vx vy vz radius fx fz); and per grain of each layer its mean fluid
    force along x and its vertical fluid force less its buoyancy (the lift,
    with the vertical drag of the pores' flow), both over its submerged
    weight (rho_s - rho) g V (the bed's 2650 and 1000 kg/m3); last, that
    vertical force averaged over the surface layer: the grains centred
    within one mean diameter below the 5 % highest centres; then how F_x/W
    spreads over that layer's grain samples (mean, median, 90th and 99th
    percentile, coefficient of variation)."""
    t0 = fluxWindow(run)[3]
    bins = {}
    lift = {}
    count = {}
    nUsed = 0
    zTop = []
    surface = []
    surfaceFx = []
    for header, atoms in windowDumps(run, t0):
        if len(header) < 12:
            continue
        rows = []
        for w in atoms:
            r = float(w[7])
            V = 4.0/3.0*math.pi*r**3
            weight = (2650.0 - 1000.0)*9.81*V
            rows.append((float(w[3]), float(w[8]),
                         float(w[8])/weight,
                         (float(w[9]) - 1000.0*9.81*V)/weight))
        nUsed += 1
        zs = sorted(row[0] for row in rows)
        zTop.append(mean(zs[-max(len(zs)//20, 1):]))
        # the surface layer: centres within one mean diameter below the
        # 5 % highest (the grains whose tops are in the flow)
        dMean = 2.0*mean([float(w[7]) for w in atoms])
        for z, fx, fxW, liftW in rows:
            if zTop[-1] - dMean <= z <= zTop[-1]:
                surface.append(liftW)
                surfaceFx.append(fxW)
        for z, fx, fxW, liftW in rows:
            b = int(z/0.005)
            bins[b] = bins.get(b, 0.0) + fx
            lift[b] = lift.get(b, (0.0, 0.0))
            lift[b] = (lift[b][0] + fxW, lift[b][1] + liftW)
            count[b] = count.get(b, 0) + 1
    if not nUsed:
        sys.exit('%s: no dumps with the fluid force in the window' % run)
    total = sum(bins.values())
    print('%s: %d dumps (t >= %.3g s); the 5 %% highest grain centres at '
          'z = %.4f m' % (run, nUsed, t0, mean(zTop)))
    print('%-16s %-8s %-10s %-12s %-8s %s' % (
        'z of centres mm', 'grains', 'share Fx', 'cumulative', 'Fx/W',
        '(Fz - buoyancy)/W'))
    cum = 0.0
    for b in sorted(bins, reverse=True):
        cum += bins[b]/total
        print('%-16s %-8.1f %-10.3f %-12.3f %-8.3f %.3f' % (
            '%g-%g' % (5*b, 5*b + 5), count[b]/nUsed, bins[b]/total, cum,
            lift[b][0]/count[b], lift[b][1]/count[b]))
    print('surface layer (centres within one mean diameter below the 5 %% '
          'highest): %d grain samples, (Fz - buoyancy)/W %.4f'
          % (len(surface), mean(surface) if surface else float('nan')))
    if surfaceFx:
        v = sorted(surfaceFx)
        m = mean(v)
        sd = math.sqrt(mean([(x - m)**2 for x in v]))
        pick = lambda p: v[min(int(p*len(v)), len(v) - 1)]
        print('surface layer Fx/W: mean %.3f, median %.3f, 90th percentile '
              '%.3f, 99th %.3f, coefficient of variation %.2f'
              % (m, pick(0.5), pick(0.9), pick(0.99), sd/m if m else
                 float('nan')))


def flagship():
    """Estimate of the Shields number in the flagship's overtopping
    (landslideDamBreach, seed Tables 2-3): discharge per unit width q of
    scenarios C1-C4 (5-20 l/s in the 0.5 m flume; the small slice scales Q
    with its width, so q is the same), grains 20-40 mm (C: d50 30 mm).
      crest (flat): critical depth h_c = (q^2/g)^(1/3), friction slope from
        Manning-Strickler, n = d50^(1/6)/21.1, tau = rho g h S_f
      downstream face (25 degrees): normal depth from Manning-Strickler,
        q = h^(5/3) sin(beta)^(1/2)/n, tau = rho g h sin(beta)
    An estimate: uniform flow on a 0.3 m face is not reached, and h < d."""
    beta = math.radians(25.0)
    print('%-9s %-8s %-9s %-9s %-9s %-9s %-22s' % (
        'scenario', 'q m2/s', 'h_c m', 'thetaCrest', 'h_face m', 'tau Pa',
        'theta face d=20/30/40 mm'))
    for name, Q in (('C1', 0.005), ('C2', 0.01), ('C3', 0.015), ('C4', 0.02)):
        q = Q/0.5
        d50 = 0.03
        n = d50**(1.0/6.0)/21.1
        hc = (q*q/G)**(1.0/3.0)
        Uc = q/hc
        Sf = (n*Uc)**2/hc**(4.0/3.0)
        thetaCrest = RHO*G*hc*Sf/((RHOS - RHO)*G*d50)
        h = (q*n/math.sqrt(math.sin(beta)))**0.6
        tau = RHO*G*h*math.sin(beta)
        th = ['%.3f' % (tau/((RHOS - RHO)*G*d)) for d in (0.02, 0.03, 0.04)]
        print('%-9s %-8.3g %-9.3g %-9.3f %-9.3g %-9.3g %s' % (
            name, q, hc, thetaCrest, h, tau, ' / '.join(th)))


def internalField(path, vector=False):
    """The internalField of an ASCII OpenFOAM field file (nonuniform)."""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<\w+>\s+(\d+)\s*\(",
                  text)
    if not m:
        sys.exit('%s: no nonuniform internalField' % path)
    n = int(m.group(1))
    body = text[m.end():]
    if vector:
        rows = re.findall(r"\(([^()]*)\)", body)[:n]
        return [[float(x) for x in r.split()] for r in rows]
    return [float(x) for x in body.split(')')[0].split()[:n]]


def nearBed(run):
    """The turbulence the bed's grains see: per cell layer of the run's last
    time the means of eps, u, k and what the fluctuations of the grains
    there have (streamwise r.m.s. 1.05 sqrt(k) over u, eddy lifetime
    l_e/max(sqrt(2k/3), u), l_e = C_mu^0.75 k^1.5/epsilon, epsilon =
    C_mu k omega: velocityFluctuation source turbulence), k over u*^2, the
    Reynolds shear stress nut du/dz over u*^2 (du/dz from the layers
    above and below) and the streamwise r.m.s. over u that it gives with
    velocityFluctuation size shearStress (2.30 sqrt(nut du/dz)); the layer
    holding the bed's surface (the lowest with eps > 0.6) marked."""
    st = settings(run)
    monodisperse(run, st)
    times = [d for d in os.listdir(run)
             if re.fullmatch(r'[0-9.]+', d) and float(d) > 0]
    t = max(times, key=float)
    nx, ny = int(st['nx']), int(st['ny'])
    cell = float(st['lz'])/int(st['nz'])
    k = internalField(os.path.join(run, t, 'k'))
    om = internalField(os.path.join(run, t, 'omega'))
    eps = internalField(os.path.join(run, t, 'voidfraction'))
    U = internalField(os.path.join(run, t, 'U'), True)
    nut = internalField(os.path.join(run, t, 'nut'))
    ustar2 = float(st['theta'])*(RHOS - RHO)*G*0.01/RHO
    print('%s at t = %s s (u*^2 = %.4g m2/s2)' % (run, t, ustar2))
    print('%-8s %-6s %-7s %-8s %-7s %-9s %-8s %-9s %-9s %s' % (
        'z[m]', 'eps', 'u[m/s]', 'k', 'k/u*^2', 'sigma/u', 'T[ms]',
        'R/u*^2', 'sigmaR/u', ''))
    surface = None
    layers = len(k)//(nx*ny)
    uLayer = layerMeans([v[0] for v in U], nx*ny)
    for j in range(layers):
        cells = range(j*nx*ny, (j + 1)*nx*ny)
        e = mean([eps[c] for c in cells])
        u = uLayer[j]
        # central difference in the interior (as fvc::grad there);
        # one-sided at the ends (the bottom layer is the frozen bed)
        lo, hi = max(j - 1, 0), min(j + 1, layers - 1)
        dudz = (uLayer[hi] - uLayer[lo])/((hi - lo)*cell)
        R = mean([nut[c] for c in cells])*abs(dudz)
        kk = mean([k[c] for c in cells])
        w = mean([om[c] for c in cells])
        epsT = 0.09*kk*w
        le = 0.09**0.75*kk**1.5/epsT if epsT > 0 else 0
        T = le/max(math.sqrt(2*kk/3), abs(u)) if kk > 0 else 0
        mark = ''
        if surface is None and e > 0.6:
            surface = j
            mark = '<- the bed surface'
        print('%-8.3f %-6.3f %-7.3f %-8.4f %-7.3f %-9.3f %-8.3g %-9.3f %-9.3f %s' % (
            (j + 0.5)*cell, e, u, kk, kk/ustar2,
            1.052*math.sqrt(kk)/abs(u) if abs(u) > 1e-9 else float('nan'),
            1e3*T, R/ustar2,
            2.30*math.sqrt(R)/abs(u) if abs(u) > 1e-9 else float('nan'),
            mark))


def layerVelocity(run, t0):
    """Per cell layer the mean streamwise fluid velocity and fluid fraction,
    averaged over the run's written times in the window (t >= t0)."""
    st = settings(run)
    nxy = int(st['nx'])*int(st['ny'])
    times = [d for d in os.listdir(run) if re.fullmatch(r'[0-9.]+', d)
             and float(d) >= t0 - 1e-9 and os.path.exists(
                 os.path.join(run, d, 'U'))]
    if not times:
        sys.exit('%s: no written fields at t >= %g' % (run, t0))
    u, e = None, None
    for t in times:
        U = internalField(os.path.join(run, t, 'U'), True)
        eps = internalField(os.path.join(run, t, 'voidfraction'))
        uj = layerMeans([v[0] for v in U], nxy)
        ej = layerMeans(eps, nxy)
        u = uj if u is None else [a + b for a, b in zip(u, uj)]
        e = ej if e is None else [a + b for a, b in zip(e, ej)]
    return [x/len(times) for x in u], [x/len(times) for x in e]


def mobileRow(run):
    """How many grains move and how fast, over a run's averaging window
    (the grains faster than 0.05 m/s): theta, q*, n d^2 (their number per
    bed area d^2, DEM/flux.dat every 5 ms), V_s (their mean streamwise
    velocity, the dumps post/grains.*.txt), u* and the mean fluid velocity
    u_surf of the cell layer holding the bed's surface (the lowest with
    eps > 0.6, averaged over the fields written in the window). None
    where no grain in the dumps is that fast."""
    s, flux, T, t0, tHalf, win = fluxWindow(run)
    monodisperse(run, s)
    area = s['lx']*s['ly']
    vx = []
    nDumps = 0
    for header, atoms in windowDumps(run, t0):
        nDumps += 1
        vx += [float(w[4]) for w in atoms if float(w[4]) > 0.05]
    if not nDumps:
        sys.exit('%s: no grain dumps in the window t >= %g' % (run, t0))
    if not vx:
        return None
    uLayer, eLayer = layerVelocity(run, t0)
    surf = [j for j, e in enumerate(eLayer) if e > 0.6]
    th = s['theta']
    return {
        'theta': th,
        'qstar': mean([r[1] for r in win])/QREF,
        'nd2': mean([r[4] for r in win])/area*D**2,
        'Vs': mean(vx),
        'ustar': math.sqrt(th*S1*G*D),
        'uSurf': uLayer[surf[0]] if surf else float('nan'),
    }


def lajeunesse(theta):
    """Lajeunesse, Malverti & Charru (2010, J. Geophys. Res. 115, F04001):
    the mean velocity of the moving grains, V_s = 4.4 (u* - u*c), here with
    theta_c 0.047 (m/s)."""
    return 4.4*max(math.sqrt(theta*S1*G*D) - math.sqrt(0.047*S1*G*D), 0.0)


def movingNeeded(theta, Vs):
    """The moving grains per bed area d^2 a flux of Wong & Parker's size
    needs at the speed Vs: q*_WP / ((pi/6) Vs / sqrt(R g d))."""
    return (wongParker(theta)/(math.pi/6.0*Vs/math.sqrt(S1*G*D))
            if Vs > 0 else float('nan'))


def mobile(runs):
    """Why the flux is what it is: q_s = (pi d^3/6) n V_s. Per run the
    columns of mobileRow, V_s against Lajeunesse et al.'s, the share of
    q_s the grains faster than 0.05 m/s carry ((pi d^3/6) n V_s / q_s),
    and the n d^2 Wong & Parker's flux needs at the measured V_s and at
    Lajeunesse et al.'s."""
    print('%-26s %-5s %-9s %-6s %-7s %-7s %-6s %-7s %-7s %-7s %-7s %s' % (
        'run', 'theta', 'q*', 'q*/WP', 'n d^2', 'Vs m/s', 'Vs/u*',
        'u_surf', 'Vs_LMC', 'share', 'nWP@Vs', 'nWP@LMC'))
    for run in runs:
        r = mobileRow(run)
        if r is None:
            print('%-26s no grain faster than 0.05 m/s in the dumps' % run)
            continue
        th, wp = r['theta'], wongParker(r['theta'])
        print('%-26s %-5g %-9.3g %-6.3f %-7.4f %-7.3f %-6.2f %-7.3f %-7.3f '
              '%-7.2f %-7.3f %.3f' % (
                  run, th, r['qstar'], r['qstar']/wp if wp else
                  float('nan'), r['nd2'], r['Vs'], r['Vs']/r['ustar'],
                  r['uSurf'], lajeunesse(th),
                  r['nd2']*r['Vs']/math.sqrt(S1*G*D)*math.pi/6.0/r['qstar']
                  if r['qstar'] else float('nan'),
                  movingNeeded(th, r['Vs']),
                  movingNeeded(th, lajeunesse(th))))


def mobileChart(outPng, entries):
    """The two parts of the flux against theta for several sweeps
    (label=<run prefix>, runs <prefix>.theta.*): left, the moving grains
    per bed area d^2 with the number Wong-Parker's flux needs at
    Lajeunesse et al.'s speed; right, their speed over u*, with Lajeunesse
    et al.'s and the mean fluid velocity of the bed's surface layer (open
    symbols)."""
    import glob
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, (axN, axV) = plt.subplots(1, 2, figsize=(11, 4.5))
    th = [0.048 + 0.002*i for i in range(177)]
    axN.plot(th, [movingNeeded(t, lajeunesse(t)) for t in th], 'k--',
             label="Wong-Parker's flux at Lajeunesse et al.'s speed")
    axV.plot(th, [lajeunesse(t)/math.sqrt(t*S1*G*D) for t in th], 'k--',
             label='Lajeunesse et al. (2010): 4.4 (u* - u*c)')
    markers = 'osD^vP'
    for k, spec in enumerate(entries):
        label, prefix = spec.rsplit('=', 1)
        runs = sorted(glob.glob(prefix + '.theta.*'),
                      key=lambda r: float(r.rsplit('.theta.', 1)[1]))
        rows = [r for r in (mobileRow(run) for run in runs) if r]
        if not rows:
            sys.exit('mobileChart: no moving grains in %s.theta.*' % prefix)
        m = markers[k % len(markers)]
        t = [r['theta'] for r in rows]
        line, = axN.plot(t, [r['nd2'] for r in rows], m + '-', label=label)
        c = line.get_color()
        axV.plot(t, [r['Vs']/r['ustar'] for r in rows], m + '-', color=c,
                 label=label + ': grains')
        axV.plot(t, [r['uSurf']/r['ustar'] for r in rows], m + ':',
                 mfc='none', color=c, label=label + ': fluid, surface layer')
    axN.set_yscale('log')
    axN.set_xlabel(r'Shields number $\theta$')
    axN.set_ylabel(r'moving grains per bed area, $n d^2$')
    axN.set_title('How many grains move (faster than 0.05 m/s)')
    axV.set_xlabel(r'Shields number $\theta$')
    axV.set_ylabel(r'mean velocity / $u_*$')
    axV.set_title('How fast they move')
    axV.set_ylim(0, 4)
    for ax in (axN, axV):
        ax.set_xlim(0, 0.42)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(outPng, dpi=120)
    print('wrote %s' % outPng)


def wilcockCrowe(tau, classes):
    """Wilcock & Crowe (2003, J. Hydraul. Eng. 129(2), 120-128), the
    surface-based transport of each size class of a gravel bed without
    sand (F_s = 0): the reference Shields number of the surface's mean
    size tau*_rm = 0.021 + 0.015 exp(-20 F_s) = 0.036 (their Eq. 6), the
    hiding function tau_ri / tau_rm = (D_i/D_sm)^b, b = 0.67 / (1 +
    exp(1.5 - D_i/D_sm)) (Eq. 3-4), and W*_i = 0.002 phi^7.5 below phi =
    1.35, 14 (1 - 0.894/phi^0.5)^4.5 above (Eq. 7), phi = tau/tau_ri,
    with q_i = W*_i F_i u*^3 / ((s - 1) g). classes: (D_i m, F_i surface
    share); D_sm their geometric mean (their Eq. uses it in psi units).
    Returns per class (tau_ri Pa, W*_i, q_i m2/s)."""
    dsm = math.exp(sum(f*math.log(d) for d, f in classes)/
                   sum(f for d, f in classes))
    taurm = 0.036*(RHOS - RHO)*G*dsm
    ustar3 = (tau/RHO)**1.5
    out = []
    for d, f in classes:
        b = 0.67/(1.0 + math.exp(1.5 - d/dsm))
        tauri = taurm*(d/dsm)**b
        phi = tau/tauri
        w = (0.002*phi**7.5 if phi < 1.35
             else 14.0*(1.0 - 0.894/math.sqrt(phi))**4.5)
        out.append((tauri, w, w*f*ustar3/(S1*G)))
    return out


def fractions(run):
    """Which grains move, on a graded bed (Allrun -grading): per size
    class over the averaging window (the dumps post/grains.*.txt), its
    share of the mobile bed's mass f_i, its share F_i of the bed's surface
    seen from above (point counts, as flume photographs give Wilcock &
    Crowe's F_i: on a grid of 1 mm, periodic in x and y, the mobile grain
    whose sphere reaches highest over each point, moving or not), its
    flux q_i = sum of V_p u_p,x / (lx ly), the share p_i = q_i / q of the
    flux, the share of its exposed grains (a quarter or more of their
    cross-section seen from above) that move (faster than 0.05 m/s) and
    the mean streamwise fluid force on those at rest over their submerged
    weight; against Wilcock & Crowe at the imposed stress. The frozen
    grains (DEM/in.pour: centres below 1.5 r in the poured bed, found by
    their ids in post/grains.0.txt) are no part of the bed's shares. The
    mobility ratio M = (q_1/F_1)/(q_n/F_n), finest over coarsest, is 1
    for equal mobility; Wilcock & Crowe give M > 1 (the fine grains move
    more, per share of the surface); M is also given for each half of the
    window (its spread). Writes <run>/fractions.summary."""
    s, flux, T, t0, tHalf, win = fluxWindow(run)
    area = s['lx']*s['ly']
    if not os.path.exists(os.path.join(run, 'post', 'grains.0.txt')):
        sys.exit('%s: no post/grains.0.txt (the bed at the start)' % run)
    frozen = set()
    for header, atoms in windowDumps(run, 0.0):
        cols = header[2:]
        iid, iz, ir = (cols.index(k) for k in ('id', 'z', 'radius'))
        frozen = set(w[iid] for w in atoms
                     if float(w[iz]) < 1.5*float(w[ir]))
        break
    h = 0.001                                   # the surface's grid, m
    nx, ny = int(round(s['lx']/h)), int(round(s['ly']/h))
    bulk, moving, nSurf, fxW = {}, {}, {}, {}
    # per half of the window: the classes' summed flux and surface points
    halfQ, halfF, halfN = ({}, {}), ({}, {}), [0, 0]
    nDumps = 0
    for t, header, atoms in windowDumps(run, t0, withTime=True):
        cols = header[2:]
        ix = [cols.index(k) for k in ('x', 'y', 'z', 'vx', 'radius')]
        iid = cols.index('id')
        ifx = cols.index('v_fxFluid') if 'v_fxFluid' in cols else None
        g = [tuple(float(w[i]) for i in ix)
             + (float(w[ifx]) if ifx is not None else float('nan'),
                w[iid] in frozen) for w in atoms]
        if not g:
            continue
        nDumps += 1
        k2 = 0 if t < tHalf else 1
        halfN[k2] += 1
        # the surface seen from above: per grid point the highest reach of
        # a mobile grain over it
        best = {}
        for k, (x, y, z, vx, r, fx, fz) in enumerate(g):
            if fz:
                continue
            for i in range(int(math.ceil((x - r)/h)), int((x + r)//h) + 1):
                for j in range(int(math.ceil((y - r)/h)),
                               int((y + r)//h) + 1):
                    rho2 = (i*h - x)**2 + (j*h - y)**2
                    if rho2 > r*r:
                        continue
                    top = z + math.sqrt(r*r - rho2)
                    key = (i % nx, j % ny)
                    if key not in best or top > best[key][0]:
                        best[key] = (top, k)
        seen = {}
        for top, k in best.values():
            seen[k] = seen.get(k, 0) + 1
        for k, (x, y, z, vx, r, fx, fz) in enumerate(g):
            d = round(2000*r, 1)            # mm, the class
            vol = math.pi/6*(2*r)**3
            halfQ[k2][d] = halfQ[k2].get(d, 0.0) + vol*vx/area
            if fz:
                continue
            bulk[d] = bulk.get(d, 0.0) + vol
            halfF[k2][d] = halfF[k2].get(d, 0.0) + seen.get(k, 0)
            if seen.get(k, 0) >= 0.25*math.pi*r*r/(h*h):
                nSurf[d] = nSurf.get(d, 0) + 1
                if vx > 0.05:
                    moving[d] = moving.get(d, 0) + 1
                else:
                    fxW.setdefault(d, []).append(
                        fx/((RHOS - RHO)*G*vol))
    if not nDumps:
        sys.exit('%s: no grain dumps in the window t >= %g' % (run, t0))
    ds = sorted(bulk)
    if len(ds) < 2:
        sys.exit('%s: one grain size only (%s mm): fractions needs a graded '
                 'bed (Allrun -grading)' % (run, ' '.join('%g' % d for d in ds)))
    q = {d: halfQ[0].get(d, 0.0) + halfQ[1].get(d, 0.0)
         for d in set(halfQ[0]) | set(halfQ[1])}
    surf = {d: halfF[0].get(d, 0.0) + halfF[1].get(d, 0.0) for d in ds}
    qt = sum(q[d] for d in ds)
    bt, st = sum(bulk.values()), sum(surf.values())
    tau = s['forcing']*s['depth']
    wc = wilcockCrowe(tau, [(d/1000, surf.get(d, 0.0)/st) for d in ds])
    qwct = sum(w[2] for w in wc)
    rows = []
    for d, w in zip(ds, wc):
        F = surf.get(d, 0.0)/st
        rows.append({'d_mm': d, 'f': bulk[d]/bt, 'F': F,
                     'q': q[d]/nDumps, 'p': q[d]/qt if qt else float('nan'),
                     'qOverF': q[d]/nDumps/F if F else float('nan'),
                     'moving': moving.get(d, 0)/nSurf[d] if nSurf.get(d)
                     else float('nan'),
                     'fxOverW': mean(fxW.get(d, [])),
                     'tauRef': w[0], 'pWC': w[2]/qwct if qwct else float('nan'),
                     'qOverFWC': w[2]/F if F else float('nan')})

    def ratio(qd, Fd):
        """M from class sums of q and of surface points."""
        a, b = ds[0], ds[-1]
        if not Fd.get(a) or not Fd.get(b) or not qd.get(b):
            return float('nan')
        return (qd.get(a, 0.0)/Fd[a])/(qd[b]/Fd[b])
    M = ratio(q, surf)
    Mh = [ratio(halfQ[k], halfF[k]) if halfN[k] else float('nan')
          for k in (0, 1)]
    MWC = rows[0]['qOverFWC']/rows[-1]['qOverFWC']
    print('%s: theta %g on d_ref %g mm, tau_b %.3f Pa, window %.3g-%.3g s, '
          '%d dumps' % (run, s['theta'], 1000*s['dRef'], tau, t0, T, nDumps))
    print('%-6s %-6s %-6s %-10s %-6s %-7s %-8s %-8s %-6s' % (
        'd mm', 'f_i', 'F_i', 'q_i m2/s', 'p_i', 'p_i WC', 'moving', 'Fx/W\'',
        'tau_ri'))
    for r in rows:
        print('%-6g %-6.3f %-6.3f %-10.3g %-6.3f %-7.3f %-8.3f %-8.3f %-6.2f'
              % (r['d_mm'], r['f'], r['F'], r['q'], r['p'], r['pWC'],
                 r['moving'], r['fxOverW'], r['tauRef']))
    print('mobility ratio M = (q/F) finest over coarsest: %.3g (halves of the '
          'window %.3g, %.3g; Wilcock-Crowe %.3g; 1: equal mobility); q total '
          '%.3g m2/s (Wilcock-Crowe %.3g)'
          % (M, Mh[0], Mh[1], MWC, qt/nDumps, qwct))
    with open(os.path.join(run, 'fractions.summary'), 'w') as f:
        f.write('# bedloadAnalysis.py fractions: per class d_mm f F q p pWC '
                'moving fxOverW tauRef; then M (its halves M1, M2), M_WC, q, '
                'q_WC\n')
        for r in rows:
            f.write('class %g %.6g %.6g %.6g %.6g %.6g %.6g %.6g %.6g\n' % (
                r['d_mm'], r['f'], r['F'], r['q'], r['p'], r['pWC'],
                r['moving'], r['fxOverW'], r['tauRef']))
        f.write('M %.6g\nM1 %.6g\nM2 %.6g\nM_WC %.6g\nq %.6g\nq_WC %.6g\n'
                % (M, Mh[0], Mh[1], MWC, qt/nDumps, qwct))
    return rows, M, MWC


def fractionsChart(outPng, entries):
    """Which grains move, as a chart: for runs on graded beds
    (label=<run>, several per label), left the fine class's share of the
    flux p_1 against theta, right the mobility ratio M, each beside
    Wilcock & Crowe's at the same stress and surface (open symbols)."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, (axP, axM) = plt.subplots(1, 2, figsize=(11, 4.5))
    marks = 'osD^v<>ph'
    for n, entry in enumerate(entries):
        label, runs = entry.split('=', 1)
        pts = []
        for run in runs.split(','):
            rows, M, MWC = fractions(run)
            pts.append((settings(run)['theta'], rows[0]['p'], rows[0]['pWC'],
                        M, MWC))
        pts.sort()
        # matplotlib's ten colours, then black and grey (one each per entry)
        c = ('C%d' % n if n < 10 else ('k', '0.5')[(n - 10) % 2])
        th = [p[0] for p in pts]
        axP.plot(th, [p[1] for p in pts], marks[n % len(marks)] + '-',
                 color=c, label=label)
        axP.plot(th, [p[2] for p in pts], marks[n % len(marks)] + ':',
                 color=c, mfc='none')
        axM.plot(th, [p[3] for p in pts], marks[n % len(marks)] + '-',
                 color=c, label=label)
        axM.plot(th, [p[4] for p in pts], marks[n % len(marks)] + ':',
                 color=c, mfc='none')
    axP.set_xlabel(r'$\theta$ on the geometric mean diameter')
    axP.set_ylabel('the fine class\'s share of the flux $p_1$')
    axP.set_ylim(0, 1)
    axP.set_title('filled: interDemFoam; open: Wilcock & Crowe (2003)')
    axP.legend(fontsize=8)
    axM.set_xlabel(r'$\theta$ on the geometric mean diameter')
    axM.set_ylabel(r'$M = (q_1/F_1)\,/\,(q_n/F_n)$, fine over coarse')
    axM.set_yscale('log')
    axM.axhline(1, color='k', lw=0.8, ls='--')
    axM.text(axM.get_xlim()[0], 1.05, ' equal mobility', fontsize=8)
    axM.set_title('mobility per share of the surface')
    fig.tight_layout()
    fig.savefig(outPng, dpi=120)
    print('wrote %s' % outPng)


def onsetMap(outPath, entries):
    """The measured onsets for checkDemScene (etc/sceneMaps): per model the
    last Shields number of a sweep without sustained transport and the
    first from which every run transports, from the sweeps' tables."""
    lines = ['# The onset of bedload in the bedload channel (tutorials/'
             'interDemFoam/bedload, docs/erosion.md; written by '
             'bedloadAnalysis.py onsetMap)',
             '# model: the turbulence model (simulationType laminar, or the '
             'RAS/LES model); below: the last theta without sustained '
             'transport; onset: the first theta from which every run '
             'transports; source: the sweep',
             '# model below onset source']
    for entry in entries:
        model, table = entry.split('=', 1)
        rows = [l.split() for l in open(table)
                if l.strip() and not l.startswith('#')]
        theta = [float(r[0]) for r in rows]
        transport = [int(float(r[3])) for r in rows]
        steady = [int(float(r[11])) for r in rows]
        onset = None
        for i in range(len(rows)):
            if all(transport[j] and steady[j] for j in range(i, len(rows))):
                onset = theta[i]
                break
        if onset is None:
            sys.exit('onsetMap: %s has no onset' % table)
        below = max(t for t in theta if t < onset)
        lines.append('%-12s %-6g %-6g %s' % (model, below, onset, table))
    with open(outPath, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('\n'.join(lines))


if __name__ == '__main__':
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    plot = '--noPlot' not in sys.argv
    if len(args) >= 2 and args[0] == 'run':
        for run in args[1:]:
            r = analyse(run)
            print('%s: theta %.4g (grains: %.4g), q* %.4g +- %.2g '
                  '(halves %.3g, %.3g; MPM %.4g, Wong-Parker %.4g), '
                  'transport %d, U %.3g m/s (drift %.1f %%), steady %d, '
                  'window %.3g-%.3g s'
                  % (run, r['theta'], r['thetaGrain'], r['qstar'],
                     r['qstarErr'], r['qstarHalf1'], r['qstarHalf2'],
                     r['qstarMPM'], r['qstarWongParker'], r['transport'],
                     r['U'], 100*r['Udrift'], r['steady'], r['windowStart'],
                     r['windowEnd']))
    elif len(args) >= 3 and args[0] == 'chart':
        chart(args[1], args[2:])
    elif len(args) == 2 and args[0] == 'profile':
        profile(args[1])
    elif args == ['flagship']:
        flagship()
    elif len(args) >= 3 and args[0] == 'collect':
        collect(args[1], args[2:], plot)
    elif len(args) == 2 and args[0] == 'nearBed':
        nearBed(args[1])
    elif len(args) >= 3 and args[0] == 'mobileChart':
        mobileChart(args[1], args[2:])
    elif len(args) >= 2 and args[0] == 'mobile':
        mobile(args[1:])
    elif len(args) >= 3 and args[0] == 'fractionsChart':
        fractionsChart(args[1], args[2:])
    elif len(args) >= 2 and args[0] == 'fractions':
        for run in args[1:]:
            fractions(run)
    elif len(args) >= 3 and args[0] == 'onsetMap':
        onsetMap(args[1], args[2:])
    else:
        sys.exit(__doc__)
