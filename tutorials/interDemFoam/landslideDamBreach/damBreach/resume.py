# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
"""Where an interrupted landslide-dam run goes on (Allrun -resume).

A run is a chain of pieces: the first to `firstEnd` (60 s at small scale),
then pieces of `pieceLength` (20 s), each a restart from the write at the previous piece's
end (log.interDemFoam, log.interDemFoam.to80, .to100, ...). A piece is
complete when its log has OpenFOAM's closing line `End`. A run that was stopped
(killed, machine switched off) goes on from the end of its last complete
piece, the same state an uninterrupted run restarts its next piece from,
so the resumed run gives the same results as one that was never stopped.
What the interrupted piece wrote after that state is removed (time folders
of the case and of each processor*, the pieces' postProcessing folders,
LIGGGHTS logs and dumps past that step); its solver log is kept in
interrupted/.

    damBreachResume.py CASE [--dry-run]

prints one line:
    finished                   the run is done (CASE/wallTime): analyse it
    from <time> <suffix>       the last complete piece ended at <time> s
                               and logged to log.interDemFoam<suffix>
                               (suffix "-" for the first piece); Allrun
                               applies the run-length rule there
    start                      no piece is complete: run from the start
and exits 1 with a message naming the file when the case cannot be
resumed. CASE/Allrun.run, written by Allrun when it sets the case up,
holds the run's settings (keyword value per line): firstEnd, pieceLength,
untilEnded, maxEnd, nProcs, demDt.
"""

import os
import re
import shutil
import sys

SETTINGS = "Allrun.run"
TIME_NAME = re.compile(r"^[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)?$")
DUMP_NAME = re.compile(r"^.*?[._]([0-9]+)\.(txt|vtk)$")


class ResumeError(Exception):
    pass


def read_settings(case):
    path = os.path.join(case, SETTINGS)
    if not os.path.isfile(path):
        raise ResumeError("%s: missing, and the run has not finished (no "
                          "wallTime): the case was set up by an Allrun "
                          "older than -resume, or its setup was stopped; "
                          "run it anew without -resume (which replaces the "
                          "case)" % path)
    settings = {}
    with open(path) as f:
        for line in f:
            words = line.split()
            if len(words) >= 2 and not words[0].startswith("#"):
                settings[words[0]] = " ".join(words[1:])
    need = {"firstEnd": float, "pieceLength": float, "untilEnded": str,
            "maxEnd": float, "nProcs": int, "demDt": float}
    out = {}
    for key, kind in need.items():
        if key not in settings:
            raise ResumeError("%s: keyword '%s' missing (need %s)"
                              % (path, key, ", ".join(need)))
        try:
            out[key] = kind(settings[key])
        except ValueError:
            raise ResumeError("%s: keyword '%s' is '%s', not a %s"
                              % (path, key, settings[key], kind.__name__))
    if out["untilEnded"] not in ("yes", "no"):
        raise ResumeError("%s: keyword 'untilEnded' is '%s': use yes or no"
                          % (path, out["untilEnded"]))
    if min(out["firstEnd"], out["pieceLength"], out["demDt"]) <= 0 \
            or out["nProcs"] < 1:
        raise ResumeError("%s: firstEnd, pieceLength and demDt must be "
                          "positive and nProcs at least 1" % path)
    return out


def time_name(t):
    """The suffix Allrun gives a piece ending at t (Python's '%g')."""
    return "%g" % t


def pieces(settings):
    """(log suffix, end time) of every piece the run may have, in order:
    Allrun goes on while a piece has ended before the longest run (maxEnd),
    so the last may end past it (maxEnd 250: ..., 240, 260)."""
    first = settings["firstEnd"]
    out = [("", first)]
    if settings["untilEnded"] == "yes":
        t = first
        while t < settings["maxEnd"] - 1e-6:
            t += settings["pieceLength"]
            out.append((".to" + time_name(t), t))
    return out


def log_complete(path):
    if not os.path.isfile(path):
        return False
    with open(path, errors="replace") as f:
        return any(line.strip() == "End" for line in f)


def same_time(a, b):
    """Time folder names carry 6 significant digits (timePrecision)."""
    return abs(a - b) <= 1e-6*max(1.0, abs(b))


def time_folders(folder):
    """{time: name} of the numeric folders in folder."""
    out = {}
    if os.path.isdir(folder):
        for name in os.listdir(folder):
            if TIME_NAME.match(name) and os.path.isdir(os.path.join(folder, name)):
                out[float(name)] = name
    return out


def plan(case):
    """(state, time, suffix, the last complete piece's log) of the case."""
    if os.path.isfile(os.path.join(case, "wallTime")):
        return "finished", None, None, None
    settings = read_settings(case)
    done = None
    for suffix, end in pieces(settings):
        if log_complete(os.path.join(case, "log.interDemFoam" + suffix)):
            done = (suffix, end)
        else:
            break
    if done is None:
        return "start", 0.0, None, settings
    return "from", done[1], done[0], settings


def require_state(case, t0, settings):
    """The DEM state the run goes on from must be there (checked before
    anything is removed): in the case's time folder t0, or processor0's
    when decomposed; a flume emptied of grains leaves the solver's mark."""
    root = (os.path.join(case, "processor0") if settings["nProcs"] > 1
            else case)
    match = [n for t, n in time_folders(root).items() if same_time(t, t0)]
    if not (match and any(
            os.path.isfile(os.path.join(root, match[0], f))
            for f in ("liggghts.restart", "liggghts.restart.emptied"))):
        raise ResumeError(
            "%s: no time %s with liggghts.restart (or .emptied), where "
            "the last complete piece ended: the case cannot be resumed; "
            "run it anew without -resume" % (root, time_name(t0)))


def clean(case, t0, settings, dry_run):
    """Remove what the pieces after t0 wrote; return the paths removed."""
    removed = []

    def remove(path):
        removed.append(path)
        if not dry_run:
            if os.path.isdir(path) and not os.path.islink(path):
                shutil.rmtree(path)
            else:
                os.remove(path)

    roots = [case] + sorted(
        os.path.join(case, d) for d in os.listdir(case)
        if re.match(r"^processor[0-9]+$", d))
    if t0 > 0:
        require_state(case, t0, settings)
    for root in roots:
        for t, name in sorted(time_folders(root).items()):
            if t > t0 and not same_time(t, t0):
                remove(os.path.join(root, name))
    # function objects' output of the pieces starting at t0 or later
    post = os.path.join(case, "postProcessing")
    if os.path.isdir(post):
        for fo in sorted(os.listdir(post)):
            for t, name in sorted(time_folders(os.path.join(post, fo)).items()):
                if t > t0 or same_time(t, t0):
                    remove(os.path.join(post, fo, name))
    # LIGGGHTS logs of the pieces starting at t0 or later
    for name in sorted(os.listdir(case)):
        if name == "log.liggghts" and t0 == 0:
            remove(os.path.join(case, name))
        m = re.match(r"^log\.liggghts\.(.+)$", name)
        if m and TIME_NAME.match(m.group(1)) and (
                float(m.group(1)) > t0 or same_time(float(m.group(1)), t0)):
            remove(os.path.join(case, name))
    # dumps past t0's step
    step0 = int(round(t0/settings["demDt"]))
    dumps = os.path.join(case, "post")
    if os.path.isdir(dumps):
        for name in sorted(os.listdir(dumps)):
            m = DUMP_NAME.match(name)
            if m and int(m.group(1)) > step0:
                remove(os.path.join(dumps, name))
    return removed


def keep_interrupted_logs(case, t0, settings, dry_run):
    """Move the solver logs of pieces after t0 into CASE/interrupted/."""
    moved = []
    for suffix, end in pieces(settings):
        if end < t0 or same_time(end, t0):
            continue
        log = os.path.join(case, "log.interDemFoam" + suffix)
        if os.path.isfile(log):
            moved.append(log)
            if not dry_run:
                target = os.path.join(case, "interrupted")
                os.makedirs(target, exist_ok=True)
                n = 1
                dest = os.path.join(target, os.path.basename(log))
                while os.path.exists(dest):
                    n += 1
                    dest = os.path.join(target, "%s.%d"
                                        % (os.path.basename(log), n))
                shutil.move(log, dest)
    return moved


def main(argv):
    args = [a for a in argv if a != "--dry-run"]
    dry_run = len(args) != len(argv)
    if len(args) != 1:
        print(__doc__)
        return 1
    case = args[0]
    if not os.path.isdir(case):
        print("damBreachResume.py: no case folder %s" % case, file=sys.stderr)
        return 1
    try:
        state, t0, suffix, settings = plan(case)
        if state == "finished":
            print("finished")
            return 0
        removed = clean(case, t0, settings, dry_run)
        moved = keep_interrupted_logs(case, t0, settings, dry_run)
    except ResumeError as e:
        print("damBreachResume.py: %s" % e, file=sys.stderr)
        return 1
    verb = "would remove" if dry_run else "removed"
    print("damBreachResume.py: %s: last complete piece %s; %s %d files and "
          "folders written after it; interrupted logs %s"
          % (case, "none" if state == "start"
             else "to %s s (log.interDemFoam%s)" % (time_name(t0), suffix),
             verb, len(removed),
             ", ".join(os.path.basename(m) for m in moved) or "none"),
          file=sys.stderr)
    if state == "start":
        print("start")
    else:
        print("from %s %s" % (time_name(t0), suffix or "-"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
