// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "demEngine.H"
#include "demStartState.H"
#include "demRestartFile.H"
#include "demScriptCheck.H"
#include "meshReach.H"
#include "IFstream.H"
#include "Pstream.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"

#include <mpi.h>
#include <unistd.h>
#include <cmath>
#include <fenv.h>
#include <csignal>
#include <cctype>
#include <algorithm>

// LIGGGHTS, through its installed C++ headers (libliggghts-dev)
#include "liggghts/lammps.h"
#include "liggghts/input.h"
#include "liggghts/atom.h"
#include "liggghts/atom_vec.h"
#include "liggghts/modify.h"
#include "liggghts/fix.h"
#include "liggghts/update.h"
#include "liggghts/universe.h"
#include "liggghts/domain.h"
#include "liggghts/fix_property_global.h"

namespace
{

// The fix ids couple/cfd/force registers for the exchanged per-atom arrays
const char* const dragForceFixId = "dragforce";
const char* const torqueFixId = "hdtorque";

// couple/cfd/force/implicit's per-atom drag coefficient and fluid velocity
const char* const KslFixId = "Ksl";
const char* const ufFixId = "uf";

// Each atom's unwrapped position at the start of the coupling interval and
// a flag (1 once set): the mean velocity over the interval's DEM steps is
// the displacement over the interval (velocity Verlet drifts each step with
// the velocity the step's forces see). A per-atom fix property: it moves
// with the atom between ranks and is kept in restart files.
const char* const startFixId = "interDemFoamStart";

// OpenFOAM traps floating-point exceptions (FOAM_SIGFPE); LIGGGHTS is not
// written for that: an overflow in a script or a blown-up DEM would die of
// SIGFPE inside LIGGGHTS. Trapping is off while LIGGGHTS runs; non-finite
// particle data is then caught, with a message, when the particles are read
struct fpeTrapsOff
{
    const int traps;
    fpeTrapsOff() : traps(fegetexcept()) { fedisableexcept(FE_ALL_EXCEPT); }
    ~fpeTrapsOff() { feclearexcept(FE_ALL_EXCEPT); feenableexcept(traps); }
};

// LIGGGHTS keeps the text of the command it runs in Input::line, a
// protected member: read through a pointer to member formed in a derived
// class, the one way C++ lets code outside the class name it
struct inputLineAccess : public LAMMPS_NS::Input
{
    static char* LAMMPS_NS::Input::* member()
    {
        return &inputLineAccess::line;
    }
};

const char* currentInputLine(const LAMMPS_NS::Input& input)
{
    return input.*inputLineAccess::member();
}


} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::demCoupling::demEngine::command
(
    const std::string& cmd,
    const bool isScript
)
{
    const std::string what(isScript ? "the script " + cmd : cmd);
    if (screenGuard_.valid())
    {
        screenGuard_->startCommand(what);
    }
    if (logGuard_.valid())
    {
        logGuard_->startCommand(what);
    }
    fpeTrapsOff noTraps;
    if (isScript)
    {
        lmp_->input->file(cmd.c_str());
    }
    else
    {
        lmp_->input->one(cmd.c_str());
    }
}


void Foam::demCoupling::demEngine::startLiggghts
(
    const fileName& caseDir,
    const fileName& restartFile,
    const fileName& demLog
)
{
    int mpiUp = 0;
    MPI_Initialized(&mpiUp);
    if (!mpiUp)
    {
        // A serial run: OpenFOAM did not start MPI, LIGGGHTS needs it
        MPI_Init(nullptr, nullptr);
        ownsMPI_ = true;
    }

    if (::chdir(caseDir.c_str()) != 0)
    {
        FatalErrorInFunction
            << "Cannot change to the case directory " << caseDir
            << exit(FatalError);
    }

    // On a restart the script gets the file as the index variable
    // restartFile (set before the script runs, so a script's own
    // "variable restartFile index <default>" yields to it). LIGGGHTS's
    // screen and log go through output guards (set below), so it opens
    // neither itself.
    std::string a0("liggghts"), a1("-log"), a2("none"), a3("-screen"),
        a4("none"), a5("-echo"), a6("none"), a7("-var"), a8("restartFile"),
        a9(restartFile);
    char* argv[] =
    {
        &a0[0], &a1[0], &a2[0], &a3[0], &a4[0], &a5[0], &a6[0], &a7[0],
        &a8[0], &a9[0], nullptr
    };
    const int argc = restarted_ ? 10 : 7;

    Info<< "DEM: LIGGGHTS on " << Pstream::nProcs() << " rank(s), script "
        << script_ << ", log " << demLog;
    if (restarted_)
    {
        Info<< nl << "DEM: restarting from " << restartFile;
    }
    Info<< endl;

    // A write beyond a file-size limit (ulimit -f) fails with EFBIG instead
    // of killing the process (SIGXFSZ): the failed write is then found and
    // reported (demRestartFile::commit)
    std::signal(SIGXFSZ, SIG_IGN);

    {
        fpeTrapsOff noTraps;
        lmp_ = new LAMMPS_NS::LAMMPS(argc, argv, solverComm());
    }
    openOutput(demLog);
}


void Foam::demCoupling::demEngine::openOutput(const fileName& demLog)
{
    // An error LIGGGHTS reports stops the run here, with its message and
    // the command it was running: LIGGGHTS prints it to the screen first
    // (Error::one to the screen only), so the screen's guard stops the run
    const demOutputGuard::errorHook onError =
        [this](const std::string& message)
        {
            liggghtsError(message);
        };

    screenGuard_.reset(new demOutputGuard("screen", stdout, false, onError));
    lmp_->screen = screenGuard_->stream();
    if (Pstream::master())
    {
        FILE* log = std::fopen(demLog.c_str(), "w");
        if (!log)
        {
            FatalErrorInFunction
                << "Cannot open the DEM log " << demLog << exit(FatalError);
        }
        std::fprintf(log, "LIGGGHTS (%s)\n", lmp_->universe->version);
        logGuard_.reset(new demOutputGuard(demLog, log, true));
        lmp_->logfile = logGuard_->stream();
    }
}


void Foam::demCoupling::demEngine::checkScriptResult
(
    const dictionary& couplingDict
)
{
    // Authoritative check on the live instance (the script may 'include')
    if
    (
        !lmp_->modify->find_fix_style_strict("couple/cfd", 0)
     || !lmp_->modify->find_fix_id(dragForceFixId)
    )
    {
        FatalIOErrorInFunction(couplingDict)
            << "After running " << script_ << " LIGGGHTS has no fix"
            << " couple/cfd with couple/cfd/force (no per-atom array '"
            << dragForceFixId << "')." << exit(FatalIOError);
    }
    implicitDrag_ =
        lmp_->modify->find_fix_style_strict("couple/cfd/force/implicit", 0);
    if (implicitDrag_ && (!lmp_->modify->find_fix_id(KslFixId) || !lmp_->modify->find_fix_id(ufFixId)))
    {
        FatalIOErrorInFunction(couplingDict)
            << "LIGGGHTS's couple/cfd/force/implicit in " << script_
            << " has no per-atom arrays '" << KslFixId << "' and '" << ufFixId
            << "'" << exit(FatalIOError);
    }
    command
    (
        std::string("fix ") + startFixId + " all property/atom " + startFixId
      + " vector yes no no 0 0 0 0"
    );

    if (!lmp_->atom->radius_flag || !lmp_->atom->rmass_flag)
    {
        FatalIOErrorInFunction(couplingDict)
            << "The DEM script " << script_ << " must use a granular atom"
            << " style (atom_style granular): particles need a radius and a"
            << " mass." << exit(FatalIOError);
    }

    if (!(timeStep() > 0) || !std::isfinite(timeStep()))
    {
        FatalIOErrorInFunction(couplingDict)
            << "The DEM script " << script_ << " sets timestep "
            << timeStep() << ": must be > 0 (the DEM step in seconds, a"
            << " whole fraction of the CFD deltaT and at most 20 % of the"
            << " Rayleigh time of the smallest particle)"
            << exit(FatalIOError);
    }

    checkParticleProperties(couplingDict);
    checkMaterial(couplingDict);

    // A script without a time-integration fix (nve/sphere, ...) is legal
    // (a bed held in place) but its particles never move
    bool integrates = false;
    for (int i = 0; i < lmp_->modify->nfix; ++i)
    {
        integrates = integrates || lmp_->modify->fix[i]->time_integrate;
    }
    if (!integrates)
    {
        Info<< "Warning: the DEM script " << script_ << " has no"
            << " time-integration fix (e.g. fix integr all nve/sphere): the"
            << " particles never move (meant for a bed held in place)."
            << endl;
    }
}


void Foam::demCoupling::demEngine::checkParticleProperties
(
    const dictionary& couplingDict
) const
{
    using constant::mathematical::pi;

    // The first particle of this rank without a positive, finite diameter
    // and density: its DEM id, diameter and density (id -1: none)
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    List<scalar> bad({-1, 0, 0});
    for (int i = 0; i < atom.nlocal; ++i)
    {
        const double r = atom.radius[i];
        const double rho =
            r > 0 ? atom.rmass[i]/(4.0/3.0*pi*r*r*r) : atom.rmass[i];
        if (!(r > 0) || !std::isfinite(r) || !(rho > 0) || !std::isfinite(rho))
        {
            bad = List<scalar>({scalar(atom.tag[i]), 2*r, rho});
            break;
        }
    }
    List<List<scalar>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = bad;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    for (const List<scalar>& b : all)
    {
        if (b[0] >= 0)
        {
            FatalIOErrorInFunction(couplingDict)
                << "DEM particle " << label(b[0]) << " has diameter "
                << b[1] << " m and density " << b[2] << " kg/m3 after the"
                << " DEM script " << script_ << ": every particle needs a"
                << " diameter > 0 and a density > 0 (set ... diameter D"
                << " density RHO, or the insertion's distributions)"
                << exit(FatalIOError);
        }
    }
}


void Foam::demCoupling::demEngine::checkMaterial
(
    const dictionary& couplingDict
) const
{
    // The Hertz contact's stiffness per atom type (where the script gives
    // one): E > 0 and -1 < nu <= 0.5, or the contact and the Rayleigh
    // time divide by zero
    const int nTypes = lmp_->atom->ntypes;
    for (int t = 0; t < nTypes; ++t)
    {
        scalar Et = 1, nut = 0;
        hertzProperties(t, Et, nut);
        if (!(Et > 0) || !std::isfinite(Et) || !(nut > -1 && nut <= 0.5))
        {
            FatalIOErrorInFunction(couplingDict)
                << "The DEM script " << script_ << " gives atom type "
                << t + 1 << " youngsModulus " << Et << " Pa and"
                << " poissonsRatio " << nut << ": youngsModulus must be > 0"
                << " and poissonsRatio in (-1, 0.5] (fix ... property/global"
                << " youngsModulus peratomtype ...)" << exit(FatalIOError);
        }
    }
}


void Foam::demCoupling::demEngine::liggghtsError
(
    const std::string& message
)
{
    // The log holds the message too (LIGGGHTS would have written it there
    // after the screen)
    if (logGuard_.valid())
    {
        logGuard_->append(message);
    }

    // The command LIGGGHTS was running, and where it stands in the script
    // files (the first line that holds it)
    std::string current;
    if (lmp_ && lmp_->input)
    {
        const char* line = currentInputLine(*lmp_->input);
        if (line)
        {
            current = line;
        }
    }
    while (!current.empty() && std::isspace(current.back()))
    {
        current.pop_back();
    }

    FatalErrorInFunction
        << "LIGGGHTS stopped with an error:" << nl
        << "    " << message.c_str() << nl;
    if (!current.empty())
    {
        FatalError
            << "    in the command: " << current.c_str() << nl;
        const std::string where
        (
            demScriptCheck::whereIs(current, script_, runDir_)
        );
        if (!where.empty())
        {
            FatalError << "    " << where.c_str() << nl;
        }
    }
    FatalError
        << "    (DEM script " << script_ << "; LIGGGHTS's own log: "
        << "log.liggghts in the case)" << exit(FatalError);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::demEngine::demEngine
(
    const dictionary& couplingDict,
    const Time& runTime,
    const fileName& workDir
)
:
    script_(),
    runDir_(workDir.empty() ? runTime.globalPath() : workDir),
    coupleEvery_(-1),
    lmp_(nullptr),
    ownsMPI_(false),
    firstRun_(true),
    restarted_(false),
    started_(false),
    inserts_(false),
    emptied_(false),
    nOwned_(0),
    implicitDrag_(false),
    interval_(0)
{
    // Paths of the DEM script (and inside it) are relative to the case
    // (or to workDir, where LIGGGHTS then runs and logs)

    // What the DEM starts from: demScript, or at t > 0 the verified DEM
    // state of that time with demRestartScript (the restart room)
    const demStartState start(couplingDict, runTime, runDir_);
    script_ = start.script();
    restarted_ = start.restarted();

    {
        const demScriptCheck check(script_, runDir_, couplingDict);
        coupleEvery_ = check.coupleEvery();
        inserts_ = check.inserts();
    }

    // A restarted run logs to log.liggghts.<time>: the log of the run it
    // continues is kept
    startLiggghts
    (
        runDir_,
        start.restartFile(),
        runDir_
       /(
            restarted_
          ? "log.liggghts." + runTime.timeName()
          : word("log.liggghts")
        )
    );

    command(script_, true);
    checkScriptResult(couplingDict);

    Info<< "DEM: time step " << timeStep() << " s, couple_every "
        << coupleEvery_ << ", " << nParticles() << " particle(s)" << nl
        << endl;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::demCoupling::demEngine::~demEngine()
{
    if (logGuard_.valid())
    {
        // LIGGGHTS closes its log itself
        lmp_->logfile = nullptr;
    }
    delete lmp_;
    logGuard_.clear();
    screenGuard_.clear();
    if (ownsMPI_)
    {
        int down = 0;
        MPI_Finalized(&down);
        if (!down)
        {
            MPI_Finalize();
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::demCoupling::demEngine::timeStep() const
{
    return lmp_->update->dt;
}


Foam::boundBox Foam::demCoupling::demEngine::box() const
{
    const LAMMPS_NS::Domain& domain = *lmp_->domain;
    return boundBox
    (
        point(domain.boxlo[0], domain.boxlo[1], domain.boxlo[2]),
        point(domain.boxhi[0], domain.boxhi[1], domain.boxhi[2])
    );
}


void Foam::demCoupling::demEngine::writeRestart(const Time& runTime)
{
    // An emptied DEM cannot be written either (LIGGGHTS's write_restart
    // sets the system up and stops on it): a marker file says so, and a
    // later restart from this time says why there is no DEM state
    if (emptied_ || (started_ && !inserts_ && nParticles() == 0))
    {
        demRestartFile(runTime, runTime.timeName()).markEmptied(runTime);
        Info<< "DEM: no particle left, no DEM restart file written at t = "
            << runTime.timeName() << " s (" << "liggghts.restart.emptied"
            << " says so)" << endl;
        return;
    }
    // Written to a temporary name, checked, then renamed, and the check
    // file written last: a run killed or a disk filled while writing
    // leaves no half restart file under the real name
    const demRestartFile state(runTime, runTime.timeName());
    const fileName tmp(state.writingFile());
    if (Pstream::master())
    {
        mkDir(tmp.path());
    }
    command("write_restart " + tmp);

    // What every rank's atom block in the file must hold (LIGGGHTS writes
    // one per rank, rank order, led by its length in doubles)
    int blockDoubles = lmp_->atom->avec->size_restart();
    List<int> blocks(Pstream::nProcs(), 0);
    MPI_Allgather
    (
        &blockDoubles, 1, MPI_INT, blocks.data(), 1, MPI_INT, solverComm()
    );
    labelList atomBlockDoubles(blocks.size());
    forAll(blocks, i)
    {
        atomBlockDoubles[i] = blocks[i];
    }
    state.commit(runTime, atomBlockDoubles, nParticles());
}


void Foam::demCoupling::demEngine::deleteParticles(const labelList& tags)
{
    if (tags.empty())
    {
        return;
    }
    // In chunks: LIGGGHTS reads one command line of limited length
    const label chunk = 100;
    for (label start = 0; start < tags.size(); start += chunk)
    {
        std::string cmd("group interDemFoamOutside id");
        for (label i = start; i < min(start + chunk, tags.size()); ++i)
        {
            cmd += ' ' + std::to_string(tags[i]);
        }
        command(cmd);
    }
    command("delete_atoms group interDemFoamOutside compress no");
    command("group interDemFoamOutside delete");
    if (nParticles() == 0)
    {
        // LIGGGHTS cannot sort an empty system (bin size 0): stop sorting
        command("atom_modify sort 0 0.0");
    }

    // The atom count changed: the next run needs LIGGGHTS's setup again
    firstRun_ = true;
}


Foam::scalar Foam::demCoupling::demEngine::rayleighTime
(
    scalar& dSmallest,
    scalar& ESmallest
) const
{
    using namespace LAMMPS_NS;

    dSmallest = 0;
    ESmallest = 0;
    scalar E0 = 0, nu0 = 0;
    if (!hertzProperties(0, E0, nu0))
    {
        return -1;
    }

    // Smallest Rayleigh time over the local particles, then over ranks:
    // T_R = pi r sqrt(rho/G)/(0.1631 nu + 0.8766), G = E/(2 (1 + nu))
    const Atom& atom = *lmp_->atom;
    double tR = GREAT, rMin = 0, EMin = 0;
    for (int i = 0; i < atom.nlocal; ++i)
    {
        scalar Ei = 0, nui = 0;
        hertzProperties(atom.type[i] - 1, Ei, nui);
        const double r = atom.radius[i];
        const double rho = atom.rmass[i]/(4.0/3.0*constant::mathematical::pi*r*r*r);
        const double G = Ei/(2*(1 + nui));
        const double ti =
            constant::mathematical::pi*r*std::sqrt(rho/G)/(0.1631*nui + 0.8766);
        if (ti < tR)
        {
            tR = ti;
            rMin = r;
            EMin = Ei;
        }
    }
    // The smallest over ranks, with the d and E of that particle from the
    // rank that holds it
    struct { double value; int rank; } local, global;
    local.value = tR;
    MPI_Comm_rank(solverComm(), &local.rank);
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MINLOC, solverComm());
    double dE[2] = {rMin, EMin};
    MPI_Bcast(dE, 2, MPI_DOUBLE, global.rank, solverComm());
    if (global.value >= GREAT)
    {
        return GREAT;   // no particles yet
    }
    dSmallest = 2*dE[0];
    ESmallest = dE[1];
    return global.value;
}


bool Foam::demCoupling::demEngine::hertzProperties
(
    const int type,
    scalar& E,
    scalar& nu
) const
{
    using namespace LAMMPS_NS;

    const int nTypes = lmp_->atom->ntypes;
    Fix* EFix = lmp_->modify->find_fix_property
    (
        "youngsModulus", "property/global", "peratomtype", nTypes, 0,
        "interDemFoam", false
    );
    Fix* nuFix = lmp_->modify->find_fix_property
    (
        "poissonsRatio", "property/global", "peratomtype", nTypes, 0,
        "interDemFoam", false
    );
    if (!EFix || !nuFix)
    {
        return false;
    }
    E = static_cast<FixPropertyGlobal*>(EFix)->compute_vector(type);
    nu = static_cast<FixPropertyGlobal*>(nuFix)->compute_vector(type);
    return true;
}


Foam::scalar Foam::demCoupling::demEngine::largestDiameter() const
{
    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    double dMax = 0;
    for (int i = 0; i < atom.nlocal; ++i)
    {
        dMax = std::max(dMax, 2*atom.radius[i]);
    }
    double global = 0;
    MPI_Allreduce(&dMax, &global, 1, MPI_DOUBLE, MPI_MAX, solverComm());
    return global;
}


Foam::label Foam::demCoupling::demEngine::nParticles() const
{
    int n = lmp_->atom->nlocal;
    int total = 0;
    MPI_Allreduce(&n, &total, 1, MPI_INT, MPI_SUM, solverComm());
    return total;
}


void Foam::demCoupling::demEngine::advance(const label nSteps)
{
    // Every particle gone (carried out of the domain) and none to come: the
    // DEM has nothing left to do. It is not run again: LIGGGHTS cannot set
    // up a granular run whose only atom types are the walls' (it stops with
    // "Atom types must start from 1"), and the fluid goes on without it.
    if (emptied_)
    {
        return;
    }
    if (started_ && !inserts_ && nParticles() == 0)
    {
        emptied_ = true;
        Info<< "DEM: no particle left and the script inserts none: the DEM"
            << " is no longer advanced; the fluid goes on alone" << endl;
        return;
    }

    // Where every atom starts this interval (for its mean velocity)
    {
        LAMMPS_NS::Fix* start = lmp_->modify->find_fix_id(startFixId);
        const LAMMPS_NS::Atom& atom = *lmp_->atom;
        for (int i = 0; i < atom.nlocal; ++i)
        {
            double* x0 = start->array_atom[i];
            lmp_->domain->unmap(atom.x[i], atom.image[i], x0);
            x0[3] = 1;
        }
    }
    interval_ = nSteps*timeStep();

    // The first run sets LIGGGHTS up; later ones continue where it stopped
    const std::string cmd
    (
        "run " + std::to_string(nSteps)
      + (firstRun_ ? "" : " pre no post no")
    );

    command(cmd);

    firstRun_ = false;
    started_ = true;
}


void Foam::demCoupling::demEngine::ownedParticles(particleData& owned)
{
    using constant::mathematical::pi;

    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const int nLocal = atom.nlocal;

    owned.resize(nLocal);
    LAMMPS_NS::Fix* start = lmp_->modify->find_fix_id(startFixId);
    LAMMPS_NS::Fix* Ksl =
        implicitDrag_ ? lmp_->modify->find_fix_id(KslFixId) : nullptr;
    LAMMPS_NS::Fix* uf =
        implicitDrag_ ? lmp_->modify->find_fix_id(ufFixId) : nullptr;
    for (int i = 0; i < nLocal; ++i)
    {
        const double r = atom.radius[i];
        owned.tag[i] = atom.tag[i];
        owned.type[i] = atom.type[i];
        // LIGGGHTS maps atoms back into a periodic box only when it
        // rebuilds its neighbour lists: between rebuilds a position may lie
        // up to half the skin beyond a periodic face. Wrapped here (periodic
        // directions only; the fluid mesh has the matching cyclic patches)
        double x[3] = {atom.x[i][0], atom.x[i][1], atom.x[i][2]};
        lmp_->domain->remap(x);
        owned.position[i] = vector(x[0], x[1], x[2]);
        owned.velocity[i] = vector(atom.v[i][0], atom.v[i][1], atom.v[i][2]);
        owned.omega[i] =
            atom.omega
          ? vector(atom.omega[i][0], atom.omega[i][1], atom.omega[i][2])
          : vector::zero;
        {
            // mean velocity over the interval: its displacement
            const double* x0 = start->array_atom[i];
            double xu[3];
            lmp_->domain->unmap(atom.x[i], atom.image[i], xu);
            owned.meanVelocity[i] =
                x0[3] > 0 && interval_ > 0
              ? vector(xu[0] - x0[0], xu[1] - x0[1], xu[2] - x0[2])/interval_
              : owned.velocity[i];
        }
        if (implicitDrag_)
        {
            owned.demK[i] = Ksl->vector_atom[i];
            owned.demUf[i] =
                vector(uf->array_atom[i][0], uf->array_atom[i][1], uf->array_atom[i][2]);
        }
        else
        {
            owned.demK[i] = 0;
            owned.demUf[i] = Zero;
        }
        owned.diameter[i] = 2*r;
        owned.density[i] = atom.rmass[i]/(4.0/3.0*pi*r*r*r);
        owned.cell[i] = -1;
        owned.hostProc[i] = -1;
    }
    nOwned_ = nLocal;
}


void Foam::demCoupling::demEngine::setForces
(
    const List<vector>& force,
    const scalarList& K,
    const List<vector>& Uf
)
{
    // This rank's atoms are those of the last ownedParticles(), same order
    const int nLocal = lmp_->atom->nlocal;
    if
    (
        nLocal != nOwned_ || force.size() != nOwned_
     || (K.size() && (K.size() != nOwned_ || Uf.size() != nOwned_))
     || (K.size() && !implicitDrag_)
    )
    {
        FatalErrorInFunction
            << "LIGGGHTS changed its local particles between the particle"
            << " exchange and setForces (" << nOwned_ << " -> " << nLocal
            << ", " << force.size() << " forces)" << abort(FatalError);
    }

    double** drag = lmp_->modify->find_fix_id(dragForceFixId)->array_atom;
    LAMMPS_NS::Fix* torqueFix = lmp_->modify->find_fix_id(torqueFixId);
    double** hdTorque = torqueFix ? torqueFix->array_atom : nullptr;
    double* Ksl =
        implicitDrag_ ? lmp_->modify->find_fix_id(KslFixId)->vector_atom : nullptr;
    double** uf =
        implicitDrag_ ? lmp_->modify->find_fix_id(ufFixId)->array_atom : nullptr;

    for (int i = 0; i < nLocal; ++i)
    {
        for (int k = 0; k < 3; ++k)
        {
            drag[i][k] = force[i][k];
            if (hdTorque)
            {
                hdTorque[i][k] = 0.0;
            }
            if (uf)
            {
                uf[i][k] = K.size() ? Uf[i][k] : 0.0;
            }
        }
        if (Ksl)
        {
            // no K given (demDrag explicit): the implicit fix adds no drag
            Ksl[i] = K.size() ? K[i] : 0.0;
        }
    }
}


// ************************************************************************* //
