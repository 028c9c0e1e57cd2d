// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "demStartState.H"
#include "demRestartFile.H"
#include "couplingKeywords.H"
#include "Pstream.H"

namespace
{
    // The keywords of couplingProperties read here
    const Foam::demCoupling::couplingKeywords::declare keywords
    (
        {"demScript", "demRestartScript"}
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::demStartState::demStartState
(
    const dictionary& couplingDict,
    const Time& runTime,
    const fileName& caseDir
)
:
    script_(couplingDict.get<fileName>("demScript")),
    restartFile_(),
    restarted_(false)
{
    // A run that starts after 0 continues from the DEM state of that time
    if (runTime.value() > 0)
    {
        const demRestartFile state(runTime, runTime.timeName());
        restartFile_ = demRestartFile::masterFile(runTime, runTime.timeName());
        string why;
        if (Pstream::master())
        {
            why = state.problem();
        }
        Pstream::scatter(why);
        if (!why.empty())
        {
            FatalIOErrorInFunction(runTime.controlDict())
                << "The run starts at t = " << runTime.timeName()
                << " s, but the DEM state of that time is not usable: "
                << restartFile_ << nl << "    " << why.c_str() << "." << nl
                << "    Start from an earlier complete time"
                << " (interDemFoam -restartFromLastComplete, or startFrom"
                << " startTime; startTime <t>), or from 0."
                << exit(FatalIOError);
        }
        if (!couplingDict.found("demRestartScript"))
        {
            FatalIOErrorInFunction(couplingDict)
                << "Restarting at t = " << runTime.timeName() << " s needs"
                << " the keyword demRestartScript: a LIGGGHTS script that"
                << " begins with" << nl
                << "    read_restart ${restartFile}" << nl
                << "and repeats what restart files do not hold (materials,"
                << " pair style, walls, integration and coupling fixes)."
                << exit(FatalIOError);
        }
        script_ = couplingDict.get<fileName>("demRestartScript");
        restarted_ = true;
    }

    script_.expand();
    if (!script_.isAbsolute())
    {
        script_ = caseDir/script_;
    }
}


// ************************************************************************* //
