#include "GidaspowDrag.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace demCoupling
{
namespace forceModels
{
    defineTypeNameAndDebug(GidaspowDrag, 0);
    addToRunTimeSelectionTable(forceModel, GidaspowDrag, dictionary);
}
}
}


Foam::demCoupling::forceModels::GidaspowDrag::GidaspowDrag
(
    const dictionary& coeffs
)
:
    forceModel(coeffs)
{}


Foam::demCoupling::particleForce
Foam::demCoupling::forceModels::GidaspowDrag::force
(
    const particleFluidState& s
) const
{
    using constant::mathematical::pi;

    const scalar Vp = pi/6*pow3(s.d);
    const scalar magUr = mag(s.Uf - s.Up);

    particleForce f;

    if (s.eps < ergunLimit)
    {
        // beta V_p/(1 - eps) with the (1 - eps) cancelled
        f.K = Vp
           *(
                150*(1 - s.eps)*s.muF/(s.eps*sqr(s.d))
              + 1.75*s.rhoF*magUr/s.d
            );
    }
    else
    {
        // 3/4 Cd rho |u-v|/d V_p eps^-1.65; for Re < 1000 written as
        // 3 pi mu d (1 + 0.15 Re^0.687) eps^-2.65, finite as Re -> 0
        const scalar Re = s.eps*s.d*s.rhoF*magUr/s.muF;
        if (Re < 1000)
        {
            f.K = 3*pi*s.muF*s.d*(1 + 0.15*pow(Re, 0.687))
               *pow(s.eps, -2.65);
        }
        else
        {
            f.K = 0.75*0.44*s.rhoF*magUr/s.d*Vp*pow(s.eps, -1.65);
        }
    }

    return f;
}


// ************************************************************************* //
