// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
/*---------------------------------------------------------------------------*\
Application
    checkDemScene

Description
    Tells what a coupled scene needs before it runs: the particle sizes
    against the cells, the DEM step against the Rayleigh time, the coupling
    step against the particle response time, the particle Courant number,
    and, for each void-fraction model, the expected error and stability at
    this cell size from the project's measured maps (etc/sceneMaps/), with
    a verdict (demCoupling::sceneCheck). The settings are parsed as the
    solver parses them (couplingControls, the models' selectors), so a
    setting the solver would refuse stops here too.

    Reads the mesh, constant/couplingProperties, constant/transportProperties,
    constant/g and system/controlDict; LIGGGHTS runs the DEM script's setup
    (no time step) in a scratch copy of the case's folders under $TMPDIR
    or /tmp (removed afterwards; time folders and anything above 64 MB
    left out). Writes nothing in the case. Exits 1 when a setting lies in a
    measured failure region, 0 otherwise (warnings included).

Usage
    checkDemScene [-targetError 1] [-velocity 0.1] [-shields 0.1] [-maps DIR]

    -targetError  the settling error allowed, in % (default 1)
    -velocity     the expected particle speed [m/s] for the Courant number
                  (default: the median particle's terminal velocity)
    -shields      the bed's expected Shields number: whether laminar flow
                  is enough or a turbulence model is needed to move it
                  (the measured onsets of bedload, docs/erosion.md)
    -maps         the folder of the measured tables (default
                  $INTERDEMFOAM_DIR/etc/sceneMaps)

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "demEngine.H"
#include "couplingControls.H"
#include "voidFractionModel.H"
#include "forceModel.H"
#include "sceneCheck.H"

using namespace Foam;

namespace
{
    //- Bytes in a folder (recursive), counted up to limit
    off_t folderSize(const fileName& dir, const off_t limit)
    {
        off_t total = 0;
        for (const fileName& f : readDir(dir, fileName::FILE))
        {
            total += Foam::fileSize(dir/f);
            if (total >= limit)
            {
                return total;
            }
        }
        for (const fileName& d : readDir(dir, fileName::DIRECTORY))
        {
            total += folderSize(dir/d, limit - total);
            if (total >= limit)
            {
                return total;
            }
        }
        return total;
    }

    //- The scratch folder, removed however the process ends (a FatalError
    //  included)
    fileName scratchFolder;
    void removeScratch()
    {
        if (!scratchFolder.empty())
        {
            rmDir(scratchFolder, true);
        }
    }

    //- The case's constant/couplingProperties, or none
    autoPtr<IOdictionary> readCouplingDict(const fvMesh& mesh)
    {
        IOobject couplingIO
        (
            "couplingProperties", mesh.time().constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
        if (!couplingIO.typeHeaderOk<IOdictionary>(true))
        {
            return nullptr;
        }
        return autoPtr<IOdictionary>::New(couplingIO);
    }

    //- The DEM script must exist (named with its keyword)
    void requireScript(const dictionary& couplingDict, const fileName& caseDir)
    {
        fileName path(couplingDict.get<fileName>("demScript"));
        path.expand();
        if (!path.isAbsolute())
        {
            path = caseDir/path;
        }
        if (!isFile(path))
        {
            FatalIOErrorInFunction(couplingDict)
                << "Cannot open the DEM script " << path << " (keyword"
                << " demScript, relative to the case)" << exit(FatalIOError);
        }
    }

    //- A scratch copy of the case for LIGGGHTS to run the script's setup
    //  in (read_restart, create_atoms, walls, materials: the particles as
    //  they start), so that the files the script opens (logs, fix print,
    //  dumps) leave the case as it is: every folder of the case but the
    //  time folders and decomposed copies, and the case's own files; a
    //  folder or file above 64 MB (results: dumps, VTK) is left out, a
    //  folder then made empty (the script may write into it)
    fileName scratchCopy(const fileName& caseDir)
    {
        const fileName scratch
        (
            fileName(getEnv("TMPDIR").empty() ? "/tmp" : getEnv("TMPDIR"))
           /("checkDemScene." + Foam::name(pid()))
        );
        rmDir(scratch, true);
        mkDir(scratch);
        scratchFolder = scratch;
        std::atexit(removeScratch);

        const off_t copyLimit = 64*1024*1024;
        for (const fileName& f : readDir(caseDir, fileName::FILE))
        {
            if (Foam::fileSize(caseDir/f) < copyLimit)
            {
                cp(caseDir/f, scratch/f);
            }
        }
        for (const fileName& d : readDir(caseDir, fileName::DIRECTORY))
        {
            scalar t = 0;
            if (readScalar(d, t) || d.startsWith("processor"))
            {
                continue;
            }
            if (folderSize(caseDir/d, copyLimit) < copyLimit)
            {
                cp(caseDir/d, scratch/d);
            }
            else
            {
                mkDir(scratch/d);
            }
        }
        return scratch;
    }

    //- The check: the settings parsed as the solver does, the DEM set up
    //  in the scratch copy; the number of failures
    label checkScene
    (
        const fvMesh& mesh,
        const dictionary& couplingDict,
        const demCoupling::sceneMaps& maps,
        const scalar target,
        const scalar velocity,
        const scalar shields
    )
    {
        const Time& runTime = mesh.time();
        const fileName caseDir(runTime.globalPath());

        demCoupling::couplingControls controls(couplingDict, runTime);
        const autoPtr<demCoupling::voidFractionModel> voidFraction
        (
            demCoupling::voidFractionModel::New(couplingDict, mesh)
        );
        const PtrList<demCoupling::forceModel> forces
        (
            demCoupling::forceModel::NewList(couplingDict)
        );

        requireScript(couplingDict, caseDir);
        const fileName scratch(scratchCopy(caseDir));
        autoPtr<demCoupling::demEngine> engine
        (
            new demCoupling::demEngine(couplingDict, runTime, scratch)
        );
        controls.resolveDemDrag(engine());

        demCoupling::sceneCheck check
        (
            mesh, maps, controls, voidFraction(), forces
        );
        const label failures = check.run(engine(), target, velocity, shields);
        engine.clear();
        return failures;
    }
}

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "What a coupled scene needs before it runs: particle sizes against"
        " the cells, DEM and coupling steps, and the void-fraction models'"
        " expected error and stability from the project's measured maps."
        " Exits 1 when a setting lies in a measured failure region."
    );
    argList::noParallel();
    argList::addOption
    (
        "targetError", "percent", "settling error allowed (default 1)"
    );
    argList::addOption
    (
        "velocity", "m/s",
        "expected particle speed (default: the median particle's terminal"
        " velocity)"
    );
    argList::addOption
    (
        "shields", "theta",
        "the bed's expected Shields number: is laminar flow enough, or is"
        " a turbulence model needed to move it"
    );
    argList::addOption
    (
        "maps", "dir", "folder of the measured tables (default"
        " $INTERDEMFOAM_DIR/etc/sceneMaps)"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const scalar target = args.getOrDefault<scalar>("targetError", 1);
    const scalar velocity = args.getOrDefault<scalar>("velocity", -1);
    const scalar shields = args.getOrDefault<scalar>("shields", -1);
    if (target <= 0)
    {
        FatalErrorInFunction
            << "-targetError " << target << ": give a positive error in %"
            << exit(FatalError);
    }
    const demCoupling::sceneMaps maps
    (
        args.getOrDefault<fileName>("maps", demCoupling::sceneMaps::defaultDir())
    );

    const autoPtr<IOdictionary> couplingDict(readCouplingDict(mesh));
    if (!couplingDict.valid())
    {
        Info<< "No constant/couplingProperties: a case without particles"
            << " (plain two-phase VoF), nothing to check" << nl
            << "checkDemScene: ok" << nl << "End" << nl << endl;
        return 0;
    }

    // The scene as the run starts
    if (runTime.value() > 0)
    {
        Info<< "Checked as the run starts from 0 (the case's start time is "
            << runTime.timeName() << " s)" << endl;
        runTime.setTime(instant(0, "0"), 0);
    }

    const label failures =
        checkScene(mesh, couplingDict(), maps, target, velocity, shields);

    Info<< (failures ? "checkDemScene: FAIL" : "checkDemScene: ok") << nl
        << "End" << nl << endl;

    // The exit code through UPstream::exit: once LIGGGHTS has started MPI,
    // argList's destructor ends the process with UPstream::exit(0), which
    // would hide a failure from a script
    UPstream::exit(failures ? 1 : 0);
    return failures ? 1 : 0;
}


// ************************************************************************* //
