#include "demEngine.H"
#include "IFstream.H"
#include "Pstream.H"
#include "mathematicalConstants.H"

#include <mpi.h>
#include <unistd.h>
#include <cmath>

// LIGGGHTS, through its installed C++ headers (libliggghts-dev)
#include "liggghts/lammps.h"
#include "liggghts/input.h"
#include "liggghts/atom.h"
#include "liggghts/modify.h"
#include "liggghts/fix.h"
#include "liggghts/update.h"
#include "liggghts/domain.h"

namespace
{

// The fix ids couple/cfd/force registers for the exchanged per-atom arrays
const char* const dragForceFixId = "dragforce";
const char* const torqueFixId = "hdtorque";

// Whitespace-separated words of one script line (comments removed)
Foam::wordList scriptWords(const std::string& line)
{
    std::string s(line.substr(0, line.find('#')));
    Foam::DynamicList<Foam::word> words;
    std::size_t pos = 0;
    while (true)
    {
        const std::size_t b = s.find_first_not_of(" \t\r", pos);
        if (b == std::string::npos) break;
        const std::size_t e = s.find_first_of(" \t\r", b);
        words.append(Foam::word(s.substr(b, e - b), false));
        if (e == std::string::npos) break;
        pos = e;
    }
    return Foam::wordList(std::move(words));
}

MPI_Comm solverComm()
{
    return Foam::Pstream::parRun() ? MPI_COMM_WORLD : MPI_COMM_SELF;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::demCoupling::demEngine::scanScript
(
    const fileName& script,
    const fileName& caseDir,
    const dictionary& dict,
    bool& haveCouple,
    bool& haveForce,
    const label depth
)
{
    IFstream is(script);
    if (!is.good())
    {
        FatalIOErrorInFunction(dict)
            << "Cannot open the DEM script " << script << nl
            << "    (keyword demScript, or an 'include' in it; paths are"
            << " relative to the case directory)"
            << exit(FatalIOError);
    }
    if (depth > 16)
    {
        FatalIOErrorInFunction(dict)
            << "DEM script " << script << ": 'include' nested deeper than 16"
            << " levels (a file that includes itself?)"
            << exit(FatalIOError);
    }

    // Join LIGGGHTS continuation lines ('&' at the end) while reading
    std::string line, joined;
    label lineNo = 0;
    while (is.getLine(line))
    {
        ++lineNo;
        const auto amp = line.find_last_not_of(" \t\r");
        if (amp != std::string::npos && line[amp] == '&')
        {
            joined += line.substr(0, amp) + ' ';
            continue;
        }
        joined += line;
        const wordList w(scriptWords(joined));
        joined.clear();

        if (w.size() == 2 && w[0] == "include")
        {
            fileName inc(w[1]);
            inc.expand();
            if (!inc.isAbsolute())
            {
                inc = caseDir/inc;
            }
            scanScript(inc, caseDir, dict, haveCouple, haveForce, depth + 1);
            continue;
        }
        if (w.size() < 4 || w[0] != "fix")
        {
            continue;
        }
        if (w[3] == "couple/cfd")
        {
            haveCouple = true;
            // fix <id> <group> couple/cfd couple_every <N> mpi
            if
            (
                w.size() < 7
             || (w[4] != "couple_every" && w[4] != "every")
             || w[6] != "mpi"
            )
            {
                FatalIOErrorInFunction(dict)
                    << "DEM script " << script << " line " << lineNo
                    << ": expected" << nl
                    << "    fix <id> all couple/cfd couple_every <N> mpi" << nl
                    << "(interDemFoam exchanges data through MPI in one"
                    << " process; the 'file' coupling is not supported)"
                    << exit(FatalIOError);
            }
            if (!readLabel(w[5], coupleEvery_) || coupleEvery_ < 1)
            {
                FatalIOErrorInFunction(dict)
                    << "DEM script " << script << " line " << lineNo
                    << ": couple_every must be a whole number >= 1 written"
                    << " out (not a variable), found '" << w[5] << "'"
                    << exit(FatalIOError);
            }
        }
        else if (w[3] == "couple/cfd/force" || w[3] == "couple/cfd/dragforce")
        {
            haveForce = true;
        }
    }
}


void Foam::demCoupling::demEngine::checkScript
(
    const dictionary& dict,
    const fileName& caseDir
)
{
    bool haveCouple = false;
    bool haveForce = false;
    coupleEvery_ = -1;

    scanScript
    (
        script_, caseDir, dict, haveCouple, haveForce, 0
    );

    if (!haveCouple || !haveForce)
    {
        FatalIOErrorInFunction(dict)
            << "The DEM script " << script_ << " lacks the coupling fix"
            << (haveCouple ? "" : " 'couple/cfd'")
            << (haveCouple || haveForce ? "" : " and the fix")
            << (haveForce ? "" : " 'couple/cfd/force'") << "." << nl
            << "    It must hold both:" << nl
            << "    fix cfd  all couple/cfd couple_every <N> mpi" << nl
            << "    fix cfd2 all couple/cfd/force" << nl
            << "    with N = deltaT (CFD) / timestep (DEM)."
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::demEngine::demEngine
(
    const dictionary& couplingDict,
    const Time& runTime
)
:
    script_(couplingDict.get<fileName>("demScript")),
    coupleEvery_(-1),
    lmp_(nullptr),
    ownsMPI_(false),
    firstRun_(true),
    counts_(),
    offsets_()
{
    // Paths of the DEM script (and inside it) are relative to the case
    const fileName caseDir(runTime.globalPath());
    script_.expand();
    if (!script_.isAbsolute())
    {
        script_ = caseDir/script_;
    }

    checkScript(couplingDict, caseDir);

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

    const fileName demLog(caseDir/"log.liggghts");
    std::string a0("liggghts"), a1("-log"), a2(demLog), a3("-echo"), a4("none");
    char* argv[] = {&a0[0], &a1[0], &a2[0], &a3[0], &a4[0], nullptr};

    Info<< "DEM: LIGGGHTS on " << Pstream::nProcs() << " rank(s), script "
        << script_ << ", log " << demLog << endl;

    lmp_ = new LAMMPS_NS::LAMMPS(5, argv, solverComm());
    lmp_->input->file(script_.c_str());

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
    if (!lmp_->atom->radius_flag || !lmp_->atom->rmass_flag)
    {
        FatalIOErrorInFunction(couplingDict)
            << "The DEM script " << script_ << " must use a granular atom"
            << " style (atom_style granular): particles need a radius and a"
            << " mass." << exit(FatalIOError);
    }

    Info<< "DEM: time step " << timeStep() << " s, couple_every "
        << coupleEvery_ << ", " << nParticles() << " particle(s)" << nl
        << endl;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::demCoupling::demEngine::~demEngine()
{
    delete lmp_;
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


Foam::label Foam::demCoupling::demEngine::nParticles() const
{
    int n = lmp_->atom->nlocal;
    int total = 0;
    MPI_Allreduce(&n, &total, 1, MPI_INT, MPI_SUM, solverComm());
    return total;
}


void Foam::demCoupling::demEngine::advance(const label nSteps)
{
    // The first run sets LIGGGHTS up; later ones continue where it stopped
    const std::string cmd
    (
        "run " + std::to_string(nSteps)
      + (firstRun_ ? "" : " pre no post no")
    );
    lmp_->input->one(cmd.c_str());
    firstRun_ = false;
}


void Foam::demCoupling::demEngine::gather(particleData& particles)
{
    using constant::mathematical::pi;

    const LAMMPS_NS::Atom& atom = *lmp_->atom;
    const int nLocal = atom.nlocal;

    // Periodic DEM directions: LIGGGHTS maps atoms back into the box only
    // when it rebuilds its neighbour lists, so between rebuilds a position
    // may lie up to half the skin beyond a periodic face; wrap it (the
    // fluid mesh there has the matching cyclic patches)
    const LAMMPS_NS::Domain& domain = *lmp_->domain;
    const int periodic[3] =
        {domain.xperiodic, domain.yperiodic, domain.zperiodic};

    // Pack: tag type x(3) v(3) omega(3) d rho
    constexpr int nValues = 13;
    std::vector<double> send(nValues*nLocal);
    for (int i = 0; i < nLocal; ++i)
    {
        double* s = &send[nValues*i];
        const double r = atom.radius[i];
        s[0] = atom.tag[i];
        s[1] = atom.type[i];
        for (int k = 0; k < 3; ++k)
        {
            double x = atom.x[i][k];
            if (periodic[k])
            {
                const double lo = domain.boxlo[k], len = domain.prd[k];
                x -= len*std::floor((x - lo)/len);
            }
            s[2 + k] = x;
            s[5 + k] = atom.v[i][k];
            s[8 + k] = atom.omega ? atom.omega[i][k] : 0.0;
        }
        s[11] = 2*r;
        s[12] = atom.rmass[i]/(4.0/3.0*pi*r*r*r);
    }

    const MPI_Comm comm = solverComm();
    int nRanks = 1;
    MPI_Comm_size(comm, &nRanks);

    counts_.setSize(nRanks);
    offsets_.setSize(nRanks);
    int n = nLocal;
    MPI_Allgather(&n, 1, MPI_INT, counts_.data(), 1, MPI_INT, comm);

    int total = 0;
    List<int> valueCounts(nRanks), valueOffsets(nRanks);
    forAll(counts_, r)
    {
        offsets_[r] = total;
        valueCounts[r] = nValues*counts_[r];
        valueOffsets[r] = nValues*total;
        total += counts_[r];
    }

    std::vector<double> all(nValues*total);
    MPI_Allgatherv
    (
        send.data(), nValues*nLocal, MPI_DOUBLE,
        all.data(), valueCounts.data(), valueOffsets.data(), MPI_DOUBLE,
        comm
    );

    particles.resize(total);
    for (int i = 0; i < total; ++i)
    {
        const double* s = &all[nValues*i];
        particles.tag[i] = label(s[0]);
        particles.type[i] = label(s[1]);
        particles.position[i] = vector(s[2], s[3], s[4]);
        particles.velocity[i] = vector(s[5], s[6], s[7]);
        particles.omega[i] = vector(s[8], s[9], s[10]);
        particles.diameter[i] = s[11];
        particles.density[i] = s[12];
    }
}


void Foam::demCoupling::demEngine::setForces
(
    const List<vector>& force,
    const List<vector>& torque
)
{
    const MPI_Comm comm = solverComm();
    const label total = force.size();

    // Sum over ranks: each particle is hosted (has its force) on one rank
    std::vector<double> local(6*total, 0.0), summed(6*total, 0.0);
    for (label i = 0; i < total; ++i)
    {
        for (int k = 0; k < 3; ++k)
        {
            local[6*i + k] = force[i][k];
            local[6*i + 3 + k] = torque.size() ? torque[i][k] : 0.0;
        }
    }
    MPI_Allreduce
    (
        local.data(), summed.data(), int(6*total), MPI_DOUBLE, MPI_SUM, comm
    );

    int rank = 0;
    MPI_Comm_rank(comm, &rank);

    LAMMPS_NS::Fix* dragFix = lmp_->modify->find_fix_id(dragForceFixId);
    LAMMPS_NS::Fix* torqueFix = lmp_->modify->find_fix_id(torqueFixId);
    double** drag = dragFix->array_atom;
    double** hdTorque = torqueFix ? torqueFix->array_atom : nullptr;

    // This rank's atoms are those it packed in the last gather, same order
    const int nLocal = lmp_->atom->nlocal;
    if (nLocal != counts_[rank])
    {
        FatalErrorInFunction
            << "LIGGGHTS changed its local particles between gather and"
            << " setForces (" << counts_[rank] << " -> " << nLocal << ")"
            << abort(FatalError);
    }
    for (int i = 0; i < nLocal; ++i)
    {
        const double* s = &summed[6*(offsets_[rank] + i)];
        for (int k = 0; k < 3; ++k)
        {
            drag[i][k] = s[k];
            if (hdTorque)
            {
                hdTorque[i][k] = s[3 + k];
            }
        }
    }
}


// ************************************************************************* //
