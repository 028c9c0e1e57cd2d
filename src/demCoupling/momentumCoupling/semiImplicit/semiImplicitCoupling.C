#include "semiImplicitCoupling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace demCoupling
{
namespace momentumCouplingModels
{
    defineTypeNameAndDebug(semiImplicitCoupling, 0);
    addToRunTimeSelectionTable
    (
        momentumCouplingModel,
        semiImplicitCoupling,
        dictionary
    );
}
}
}


Foam::demCoupling::momentumCouplingModels::semiImplicitCoupling::
semiImplicitCoupling
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    momentumCouplingModel(dict, mesh)
{}


void Foam::demCoupling::momentumCouplingModels::semiImplicitCoupling::assemble
(
    const particleData& particles,
    const voidFractionModel& voidFraction,
    const scalarList& K,
    const List<vector>&,
    const List<vector>& Fexplicit,
    volScalarField& Ksl,
    volVectorField& Us,
    volVectorField& fExplicit
) const
{
    const label n = particles.size();
    List<vector> Kv(n), VpUp(n);
    scalarList Vp(n);
    forAll(Kv, i)
    {
        Kv[i] = K[i]*particles.velocity[i];
        Vp[i] = particles.volume(i);
        VpUp[i] = Vp[i]*particles.velocity[i];
    }

    Ksl.primitiveFieldRef() = voidFraction.spread(K);
    fExplicit.primitiveFieldRef() = -voidFraction.spread(Fexplicit);

    const vectorField KvCell(voidFraction.spread(Kv));
    const scalarField solid(voidFraction.spread(Vp));
    const vectorField momentum(voidFraction.spread(VpUp));
    forAll(Us, c)
    {
        if (Ksl[c] > SMALL)
        {
            Us[c] = KvCell[c]/Ksl[c];
        }
        else if (solid[c] > SMALL)
        {
            Us[c] = momentum[c]/solid[c];
        }
        else
        {
            Us[c] = Zero;
        }
    }

    Ksl.correctBoundaryConditions();
    Us.correctBoundaryConditions();
    fExplicit.correctBoundaryConditions();
}


// ************************************************************************* //
