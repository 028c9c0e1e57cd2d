// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "diffusion.H"
#include "addToRunTimeSelectionTable.H"
#include "fvm.H"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{
namespace demCoupling
{
namespace voidFractionModels
{
    defineTypeNameAndDebug(diffusion, 0);
    addToRunTimeSelectionTable(voidFractionModel, diffusion, dictionary);
}
}
}


Foam::demCoupling::voidFractionModels::diffusion::diffusion
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    centre(dict, mesh),
    bandwidth_
    (
        inputCheck::get<scalar>
        (
            inputCheck::subDict
            (
                dict, "diffusionCoeffs", {"bandwidth", "nSteps"}
            ),
            "bandwidth",
            [](const scalar b) { return b > 0; },
            "> 0 (the width, in m, over which a particle's volume spreads)"
        )
    ),
    nSteps_
    (
        inputCheck::get<label>
        (
            dict.subDict("diffusionCoeffs"), "nSteps",
            [](const label n) { return n >= 1; },
            "a whole number >= 1 (implicit diffusion steps)"
        )
    ),
    solverControls_()
{
    // The linear solver: fvSolution's solvers.voidFractionSmoothing when
    // the case sets one, else a tight PCG (what is left unsolved is
    // particle volume lost or gained)
    const dictionary solvers
    (
        static_cast<const fvSolution&>(mesh).subOrEmptyDict("solvers")
    );
    if (solvers.found("voidFractionSmoothing"))
    {
        solverControls_ = mesh.solverDict("voidFractionSmoothing");
    }
    else
    {
        solverControls_.add("solver", "PCG");
        solverControls_.add("preconditioner", "DIC");
        solverControls_.add("tolerance", 1e-14);
        solverControls_.add("relTol", 0.0);
        solverControls_.add("maxIter", 1000);
    }

    Info<< "    diffusion: bandwidth " << bandwidth_ << " m, " << nSteps_
        << " implicit steps; solver " << solverControls_.get<word>("solver")
        << (solvers.found("voidFractionSmoothing") ? " (fvSolution"
            " solvers.voidFractionSmoothing)" : " (the default: PCG/DIC to"
            " 1e-14; fvSolution solvers.voidFractionSmoothing sets it)")
        << endl;
}


template<class Type>
void Foam::demCoupling::voidFractionModels::diffusion::smoothField
(
    Field<Type>& f
) const
{
    typedef GeometricField<Type, fvPatchField, volMesh> fieldType;

    fieldType phi
    (
        IOobject
        (
            "voidFractionSmoothing_" + word(pTraits<Type>::typeName),
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensioned<Type>(dimless, Zero),
        zeroGradientFvPatchField<Type>::typeName
    );
    phi.primitiveFieldRef() = f;
    phi.correctBoundaryConditions();

    const dimensionedScalar dT
    (
        "dT", sqr(dimLength), sqr(bandwidth_)/4/nSteps_
    );
    const dimensionedScalar one("one", dimless, 1.0);

    // The solver's per-solve report would flood the log
    const int oldDebug = SolverPerformance<Type>::debug;
    SolverPerformance<Type>::debug = 0;
    for (label step = 0; step < nSteps_; ++step)
    {
        const fieldType phi0("phi0", phi);
        fvMatrix<Type> eqn
        (
            fvm::Sp(one, phi) - fvm::laplacian(dT, phi) == phi0
        );
        eqn.solve(solverControls_);
    }
    SolverPerformance<Type>::debug = oldDebug;

    f = phi.primitiveField();
}


// ************************************************************************* //
