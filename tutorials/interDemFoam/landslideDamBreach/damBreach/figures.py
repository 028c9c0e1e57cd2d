# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""The plots: one run's (damBreach.png, profiles.png) and the eight runs'
(the seed's Figs. 8-11)."""
import os

import numpy as np

from .scenarios import SCENARIOS
from .water import smooth


def pyplot():
    """matplotlib's pyplot, drawing to files (no display)."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    return plt


def plot_case(case, table, centres, profiles, wb):
    """damBreach.png (H, its rate, [E], forces, profiles, discharges) and
    profiles.png of one run, from its damBreach.dat table."""
    plt = pyplot()

    name = os.path.basename(os.path.abspath(case))
    t = table[:, 0]
    fig, ax = plt.subplots(2, 3, figsize=(15, 8))
    ax[0, 0].plot(t, table[:, 1]*1000, 'k-', label='dam height H')
    if not np.all(np.isnan(table[:, 16])):
        ax[0, 0].plot(t, (table[:, 1] - table[:, 16])*1000, 'b--',
                      label='lake level at the crest')
        ax[0, 0].legend(fontsize=8)
    ax[0, 0].set(xlabel='t [s]', ylabel='dam height H [mm]',
                 title='Dam height (seed Fig. 10)')
    ax[0, 1].plot(t, table[:, 2]*1000, 'b-')
    ax[0, 1].axhline(0, color='grey', lw=0.5)
    ax[0, 1].set(xlabel='t [s]', ylabel='(H(t+1) - H(t))/dt [mm/s]',
                 title='Height change rate, eq. 21 (Fig. 11)')
    ax[0, 2].plot(t, table[:, 3], 'r-')
    ax[0, 2].set(xlabel='t [s]', ylabel='[E] = E/E(0)',
                 title='Dimensionless total energy, eq. 20 (Fig. 8)')
    ax[1, 0].plot(t, table[:, 9], label='normal contact |F_n|')
    ax[1, 0].plot(t, table[:, 10], label='tangential contact |F_t|')
    ax[1, 0].plot(t, table[:, 11], label='particle-fluid |F_f|')
    ax[1, 0].set(xlabel='t [s]', ylabel='mean force [N]',
                 title='Forces (seed Fig. 7)')
    ax[1, 0].legend(fontsize=8)
    for tp, h in profiles:
        ax[1, 1].plot(centres, h*1000, label='t = %g s' % tp)
    ax[1, 1].set(xlim=(2.5, 7), xlabel='x along the bed [m]',
                 ylabel='surface of resting grains [mm]',
                 title='Longitudinal profiles (seed Fig. 9)')
    ax[1, 1].legend(fontsize=8)
    if wb:
        ax[1, 2].plot(wb['t'], smooth(wb['t'], wb['qin'], 0.5)*1000,
                      label='inflow')
        ax[1, 2].plot(wb['t'], smooth(wb['t'], wb['qout'], 0.5)*1000,
                      label='outflow (outlet)')
        ax[1, 2].legend(fontsize=8)
    ax[1, 2].set(xlabel='t [s]', ylabel='discharge [l/s] (0.5 s mean)',
                 title='Water discharge')
    fig.suptitle('Landslide dam breach, %s' % name)
    fig.tight_layout()
    fig.savefig(os.path.join(case, 'damBreach.png'), dpi=110)

    fig, axp = plt.subplots(figsize=(9, 4))
    for tp, h in profiles:
        axp.plot(centres, h*1000, label='t = %g s' % tp)
    axp.set(xlim=(2.5, 7), xlabel='x along the bed [m]',
            ylabel='surface of resting grains, normal to the bed [mm]',
            title='Breach morphology, %s (seed Fig. 9)' % name)
    axp.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(case, 'profiles.png'), dpi=110)


COLOUR = {'1': 'tab:blue', '2': 'tab:green', '3': 'tab:orange',
          '4': 'tab:red'}        # by inflow
STYLE = {'C': '-', 'F': '--'}    # by material


def all_runs_figure(plt, runs, out, scale, fig_no, attr, ylabel, title):
    """One series of every run in one chart (Figs. 8 and 10)."""
    fig, ax = plt.subplots(figsize=(8, 5))
    for n in SCENARIOS:
        if n not in runs:
            continue
        r = runs[n]
        y = getattr(r, attr)*(1000 if attr == 'Hs' else 1)
        ax.plot(r.t, y, STYLE[r.material], color=COLOUR[r.level],
                label='%s (%g l/s)' % (n, 1000*r.inflow))
    ax.set(xlabel='t [s]', ylabel=ylabel,
           title='%s, all scenarios (seed Fig. %d), %s scale'
           % (title, fig_no, scale))
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'fig%d.%s.png' % (fig_no, scale)),
                dpi=110)
    plt.close(fig)


def grid_figure(plt, runs, out, scale, fig_no, draw, ylabel, xlabel, title):
    """One panel per run, a grid A-H (Figs. 9 and 11)."""
    fig, axes = plt.subplots(2, 4, figsize=(18, 7), sharex=True,
                             sharey=True)
    for k, n in enumerate(SCENARIOS):
        ax = axes[k // 4, k % 4]
        if n not in runs:
            ax.set_title('%s: no run' % n)
            continue
        more = draw(plt, ax, runs[n])
        ax.set_title('(%s) %s%s' % ('ABCDEFGH'[k], n, more))
        if k % 4 == 0:
            ax.set_ylabel(ylabel)
        if k >= 4:
            ax.set_xlabel(xlabel)
    fig.suptitle('%s, %s scale' % (title, scale))
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'fig%d.%s.png' % (fig_no, scale)),
                dpi=100)
    plt.close(fig)


def draw_profiles(plt, ax, r):
    """A run's longitudinal profiles at eight times (Fig. 9's panel)."""
    pick = np.unique(np.linspace(0, len(r.tp) - 1, 8).round().astype(int))
    cmap = plt.get_cmap('viridis')
    for j, i in enumerate(pick[1:]):
        ax.plot(r.centres, r.profiles[i]*1000,
                color=cmap(j/max(1, len(pick) - 2)), lw=1,
                label='%g s' % r.tp[i])
    ax.plot(r.centres, r.profiles[0]*1000, 'k--', lw=1, label='t = 0')
    ax.set_xlim(2.5, 7)
    ax.legend(fontsize=6, ncol=2)
    return ', %g l/s' % (1000*r.inflow)


def draw_rates(plt, ax, r):
    """A run's height-change rate, its overtopping marked (Fig. 11's
    panel)."""
    ax.plot(r.t, r.rate*1000, 'b-', lw=0.8)
    ax.axhline(0, color='grey', lw=0.5)
    if r.t_over >= 0:
        ax.axvline(r.t_over, color='r', lw=0.8, ls=':')
    return ''


def matrix_figures(runs, out, scale):
    """The seed's Figs. 8-11 from the runs present: OUT/fig<n>.<scale>.png."""
    plt = pyplot()
    for fig_no, attr, ylabel, title in (
            (10, 'Hs', 'dam height H [mm] (2 s mean)', 'Dam height'),
            (8, 'E', '[E] = E/E(0)', 'Dimensionless total energy, eq. 20')):
        all_runs_figure(plt, runs, out, scale, fig_no, attr, ylabel, title)
    for fig_no, draw, ylabel, xlabel, title in (
            (9, draw_profiles, 'surface of resting grains [mm]',
             'x along the bed [m]', 'Longitudinal profiles (seed Fig. 9)'),
            (11, draw_rates, '(H(t+dt) - H(t))/dt [mm/s]',
             't [s] (red: overtopping)',
             'Height-change rate, eq. 21 (seed Fig. 11)')):
        grid_figure(plt, runs, out, scale, fig_no, draw, ylabel, xlabel,
                    title)
