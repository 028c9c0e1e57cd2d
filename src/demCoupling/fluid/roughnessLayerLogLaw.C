// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "roughnessLayerLogLaw.H"
#include "inputCheck.H"

namespace
{

// couplingProperties' roughnessLayerCoeffs, its keywords checked
const Foam::dictionary& coeffsOf(const Foam::dictionary& couplingDict)
{
    using namespace Foam;
    if (!couplingDict.isDict("roughnessLayerCoeffs"))
    {
        FatalIOErrorInFunction(couplingDict)
            << "fluidVelocity roughnessLayer in " << couplingDict.name()
            << " needs the sub-dictionary roughnessLayerCoeffs with"
            << " roughness (k_s/D, > 0: 2.9 measured over a bed of spheres"
            << " by tests/cases/turbulentBed), bedSolidFraction (1 - eps in"
            << " the packed bed, between 0 and 1), roughnessDiameter (D [m],"
            << " the size of the bed's roughness elements, > 0),"
            << " crestAboveZeroPlane ((z_c - z_e)/D, 0.2-0.3 over packed"
            << " grains) and layerDepth ((z_c - z_t)/D, about 1)"
            << exit(FatalIOError);
    }
    return demCoupling::inputCheck::subDict
    (
        couplingDict, "roughnessLayerCoeffs",
        {
            "roughness", "bedSolidFraction", "roughnessDiameter",
            "crestAboveZeroPlane", "layerDepth"
        }
    );
}

Foam::scalar positiveOf(const Foam::dictionary& coeffs, const char* key)
{
    return Foam::demCoupling::inputCheck::get<Foam::scalar>
    (
        coeffs, key, &Foam::demCoupling::inputCheck::positive, "> 0"
    );
}

// The model from couplingProperties' roughnessLayerCoeffs, each keyword
// checked, then the crests above z0 and the troughs at or below the zero
// plane
Foam::demCoupling::roughnessLayerLogLaw checkedModel
(
    const Foam::dictionary& couplingDict
)
{
    using namespace Foam;
    using namespace Foam::demCoupling;
    const dictionary& coeffs = coeffsOf(couplingDict);
    const scalar roughness = positiveOf(coeffs, "roughness");
    const scalar bedSolidFraction =
        bedSurfaceLogLaw::readBedSolidFraction(coeffs);
    const scalar roughnessDiameter = positiveOf(coeffs, "roughnessDiameter");
    const scalar crest = positiveOf(coeffs, "crestAboveZeroPlane");
    const scalar depth = positiveOf(coeffs, "layerDepth");
    if (crest <= roughness/30)
    {
        inputCheck::notAllowed
        (
            coeffs, "crestAboveZeroPlane", crest,
            "above z0/D = roughness/30 = "
          + std::to_string(roughness/30)
          + " (the crests in the log law's range)"
        );
    }
    if (depth < crest)
    {
        inputCheck::notAllowed
        (
            coeffs, "layerDepth", depth,
            "at least crestAboveZeroPlane = "
          + std::to_string(crest)
          + " (the troughs at or below the zero plane)"
        );
    }
    return roughnessLayerLogLaw
    (
        roughness, bedSolidFraction, roughnessDiameter, crest, depth
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::roughnessLayerLogLaw::roughnessLayerLogLaw
(
    const dictionary& couplingDict
)
:
    roughnessLayerLogLaw(checkedModel(couplingDict))
{}


Foam::demCoupling::roughnessLayerLogLaw::roughnessLayerLogLaw
(
    const scalar roughness,
    const scalar bedSolidFraction,
    const scalar roughnessDiameter,
    const scalar crestAboveZeroPlane,
    const scalar layerDepth
)
:
    bedSurfaceLogLaw(roughness, bedSolidFraction),
    roughnessDiameter_(roughnessDiameter),
    crestAboveZeroPlane_(crestAboveZeroPlane),
    layerDepth_(layerDepth)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::demCoupling::roughnessLayerLogLaw::roughnessLength
(
    const scalar
) const
{
    return roughness()*roughnessDiameter_/30;
}


Foam::scalar Foam::demCoupling::roughnessLayerLogLaw::flowBottom
(
    const scalar zE,
    const bool surfaceInReach
) const
{
    if (!surfaceInReach)
    {
        return zE;
    }
    return zE + (crestAboveZeroPlane_ - layerDepth_)*roughnessDiameter_;
}


Foam::scalar Foam::demCoupling::roughnessLayerLogLaw::speedAt
(
    const scalar z,
    const scalar zE,
    const bool surfaceInReach,
    const scalar z0,
    const scalar logAbove,
    const scalar magUabove
) const
{
    const scalar zCrest = zE + crestAboveZeroPlane_*roughnessDiameter_;
    if (z >= zCrest || !surfaceInReach)
    {
        return bedSurfaceLogLaw::speedAt
        (
            z, zE, surfaceInReach, z0, logAbove, magUabove
        );
    }
    const scalar depth = layerDepth_*roughnessDiameter_;
    const scalar share = (z - (zCrest - depth))/depth;
    return
        share > 0
      ? share*bedSurfaceLogLaw::speedAt
        (
            zCrest, zE, surfaceInReach, z0, logAbove, magUabove
        )
      : 0;
}


// ************************************************************************* //
