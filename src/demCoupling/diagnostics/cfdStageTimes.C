// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "cfdStageTimes.H"
#include "error.H"

#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::demCoupling::cfdStageTimes::cfdStageTimes(const wordList& stages)
:
    stages_(stages),
    seconds_(stages.size(), Zero),
    steps_(0),
    clock_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::demCoupling::cfdStageTimes::restart()
{
    clock_.timeIncrement();
}


void Foam::demCoupling::cfdStageTimes::mark(const word& stage)
{
    const label i = stages_.find(stage);
    if (i < 0)
    {
        FatalErrorInFunction
            << "No CFD stage '" << stage << "'; the stages are " << stages_
            << exit(FatalError);
    }
    seconds_[i] += clock_.timeIncrement();
}


Foam::scalar Foam::demCoupling::cfdStageTimes::seconds
(
    const word& stage
) const
{
    const label i = stages_.find(stage);
    return i < 0 ? 0 : seconds_[i];
}


void Foam::demCoupling::cfdStageTimes::print(const fvMesh& mesh) const
{
    const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
    const scalar cellSteps = max(scalar(nCells)*steps_, scalar(1));
    // Seconds to 3 significant digits, us per cell-step likewise
    auto figure = [](const scalar x)
    {
        std::ostringstream os;
        os << std::setprecision(3) << x;
        return os.str();
    };
    scalar total = 0;
    std::string line("CFD split:");
    forAll(stages_, i)
    {
        total += seconds_[i];
        line += (i ? ", " : " ") + stages_[i] + ' ' + figure(seconds_[i])
            + " s (" + figure(1e6*seconds_[i]/cellSteps) + " us per cell-step)";
    }
    line += "; in all " + figure(total) + " s ("
        + figure(1e6*total/cellSteps) + " us per cell-step), "
        + std::to_string(nCells) + " cells, " + std::to_string(steps_)
        + " steps";
    Info<< line.c_str() << endl;
}


// ************************************************************************* //
