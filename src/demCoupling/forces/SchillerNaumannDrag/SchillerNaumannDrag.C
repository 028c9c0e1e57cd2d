#include "SchillerNaumannDrag.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(SchillerNaumannDrag, 0);
    addToRunTimeSelectionTable(forceModel, SchillerNaumannDrag, dictionary);
}
}
}


Foam::demCoupling::forceModels::SchillerNaumannDrag::SchillerNaumannDrag
(
    const dictionary& coeffs
)
:
    forceModel(coeffs)
{}


Foam::demCoupling::particleForce
Foam::demCoupling::forceModels::SchillerNaumannDrag::force
(
    const particleFluidState& s
) const
{
    using constant::mathematical::pi;

    const scalar magUr = mag(s.Uf - s.Up);
    const scalar Re = s.d*s.rhoF*magUr/s.muF;

    particleForce f;
    if (Re < 1000)
    {
        f.K = 3*pi*s.muF*s.d*(1 + 0.15*pow(Re, 0.687));
    }
    else
    {
        f.K = 0.5*0.44*s.rhoF*pi/4*sqr(s.d)*magUr;
    }
    return f;
}


// ************************************************************************* //
