// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
/*---------------------------------------------------------------------------*\
Description
    k-omega SST (Menter 1994, OpenFOAM's kOmegaSST) for the VoF mixture's
    phase model, PhaseCompressibleTurbulenceModel of the immiscible
    incompressible two-phase mixture with eps as its phase fraction
    (demCoupling::epsTurbulence). OpenFOAM's library of that model
    (libCompressibleTwoPhaseMixtureTurbulenceModels, MPPICInterFoam's)
    holds Stokes, kEpsilon, kOmega, Smagorinsky and kEqn; this adds
    kOmegaSST to its selection table.

\*---------------------------------------------------------------------------*/

#include "fvm.H"
#include "fvc.H"
#include "fvOptions.H"
#include "PhaseCompressibleTurbulenceModel.H"
#include "immiscibleIncompressibleTwoPhaseMixture.H"
#include "addToRunTimeSelectionTable.H"
#include "makeTurbulenceModel.H"
#include "RASModel.H"
#include "kOmegaSST.H"

namespace Foam
{
    // The names the model library gives its types
    typedef PhaseCompressibleTurbulenceModel
    <
        immiscibleIncompressibleTwoPhaseMixture
    > immiscibleIncompressibleTwoPhaseMixturePhaseCompressibleTurbulenceModel;

    typedef RASModel
    <
        immiscibleIncompressibleTwoPhaseMixturePhaseCompressibleTurbulenceModel
    > RASimmiscibleIncompressibleTwoPhaseMixturePhaseCompressibleTurbulenceModel;
}

makeTemplatedTurbulenceModel
(
    immiscibleIncompressibleTwoPhaseMixturePhaseCompressibleTurbulenceModel,
    RAS,
    kOmegaSST
);


// ************************************************************************* //
