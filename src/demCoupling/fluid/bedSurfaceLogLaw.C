// interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
// Copyright (C) 2026 the interDemFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
#include "bedSurfaceLogLaw.H"
#include "inputCheck.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::bedSurfaceLogLaw::bedSurfaceLogLaw
(
    const dictionary& couplingDict
)
:
    roughness_(0),
    bedSolidFraction_(0)
{
    if (!couplingDict.isDict("bedSurfaceLogLawCoeffs"))
    {
        FatalIOErrorInFunction(couplingDict)
            << "fluidVelocity bedSurfaceLogLaw in " << couplingDict.name()
            << " needs the sub-dictionary bedSurfaceLogLawCoeffs with"
            << " roughness (k_s/d, the bed's Nikuradse roughness over the"
            << " grain diameter, > 0: 2.9 measured over a bed of spheres by"
            << " tests/cases/turbulentBed) and bedSolidFraction (1 - eps in"
            << " the packed bed as the void-fraction field shows it, between"
            << " 0 and 1)" << exit(FatalIOError);
    }
    const dictionary& coeffs = inputCheck::subDict
    (
        couplingDict, "bedSurfaceLogLawCoeffs",
        {"roughness", "bedSolidFraction"}
    );
    roughness_ = inputCheck::get<scalar>
    (
        coeffs, "roughness", &inputCheck::positive, "> 0 (k_s/d)"
    );
    bedSolidFraction_ = readBedSolidFraction(coeffs);
}


Foam::demCoupling::bedSurfaceLogLaw::bedSurfaceLogLaw
(
    const scalar roughness,
    const scalar bedSolidFraction
)
:
    roughness_(roughness),
    bedSolidFraction_(bedSolidFraction)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::demCoupling::bedSurfaceLogLaw::readBedSolidFraction
(
    const dictionary& coeffs
)
{
    return inputCheck::get<scalar>
    (
        coeffs, "bedSolidFraction",
        [](const scalar v) { return v > 0 && v < 1; },
        "between 0 and 1, both excluded (1 - eps in the packed bed)"
    );
}


void Foam::demCoupling::bedSurfaceLogLaw::verticalExtent
(
    const fvMesh& mesh,
    const label celli,
    const vector& up,
    scalar& zLow,
    scalar& zHigh
)
{
    zLow = GREAT;
    zHigh = -GREAT;
    for (const label pointi : mesh.cellPoints()[celli])
    {
        const scalar z = mesh.points()[pointi] & up;
        zLow = min(zLow, z);
        zHigh = max(zHigh, z);
    }
}


Foam::scalar Foam::demCoupling::bedSurfaceLogLaw::zeroPlane
(
    const scalar zLow,
    const scalar zHigh,
    const scalar solidHost,
    const scalar solidBelow
) const
{
    const scalar dz = zHigh - zLow;
    const scalar filledBelow = min(max(solidBelow, 0)/bedSolidFraction_, 1);
    const scalar filledHost = min(max(solidHost, 0)/bedSolidFraction_, 1);
    return zLow - dz + (filledBelow + filledHost)*dz;
}


Foam::scalar Foam::demCoupling::bedSurfaceLogLaw::speedAt
(
    const scalar z,
    const scalar zE,
    const bool,
    const scalar z0,
    const scalar logAbove,
    const scalar magUabove
) const
{
    const scalar height = z - zE;
    // the law below the anchor, no higher than it above
    return
        height > z0
      ? magUabove*min(Foam::log(height/z0)/logAbove, scalar(1))
      : 0;
}


Foam::vector Foam::demCoupling::bedSurfaceLogLaw::velocity
(
    const scalar zCentre,
    const scalar d,
    const scalar zLow,
    const scalar zHigh,
    const scalar solidHost,
    const scalar solidBelow,
    const vector& Uabove,
    const vector& Uhost,
    const scalar solidAbove
) const
{
    const scalar r = 0.5*d;
    const scalar zE = zeroPlane(zLow, zHigh, solidHost, solidBelow);
    const scalar z0 = roughnessLength(d);
    // The bed's surface within the host cell or the cell below (the zero
    // plane below the host cell's top), or in the cell above (those two
    // packed, the cell above not)
    const bool surfaceInReach =
        zE < zHigh || solidAbove < bedSolidFraction_;
    const scalar zBottom = flowBottom(zE, surfaceInReach);
    const scalar zAbove = zHigh + 0.5*(zHigh - zLow);
    const scalar magUabove = mag(Uabove);

    // Wholly sheltered, or no profile to anchor (the cell above still in
    // the bed's roughness, or no flow above)
    if
    (
        zCentre + r <= zBottom || zAbove - zE <= 2*z0 || magUabove < VSMALL
    )
    {
        return Uhost;
    }

    // The exposed part of the cross-section: z = zCentre - r cos(phi),
    // phi from phiLow (the flow's bottom, or the grain's) to pi; the
    // width there is 2 r sin(phi) and dz = r sin(phi) dphi
    const scalar cosLow = min(max((zCentre - zBottom)/r, -1), 1);
    const scalar phiLow = Foam::acos(cosLow);
    const scalar logAbove = Foam::log((zAbove - zE)/z0);
    const scalar dphi = (constant::mathematical::pi - phiLow)/nQuadrature;
    scalar u2Area = 0;
    for (label i = 0; i < nQuadrature; ++i)
    {
        const scalar phi = phiLow + (i + 0.5)*dphi;
        const scalar u = speedAt
        (
            zCentre - r*Foam::cos(phi), zE, surfaceInReach, z0, logAbove,
            magUabove
        );
        const scalar s = Foam::sin(phi);
        u2Area += sqr(u)*2*sqr(r)*sqr(s)*dphi;
    }
    const scalar area = constant::mathematical::pi*sqr(r);
    // int_phiLow^pi 2 r^2 sin^2 = r^2 (pi - phiLow + sin cos at phiLow)
    const scalar exposedArea =
        sqr(r)
       *(
            constant::mathematical::pi - phiLow
          + Foam::sin(phiLow)*Foam::cos(phiLow)
        );
    // The exposed and the sheltered parts in quadrature (drag goes with
    // u^2: a uniform flow gives its own speed), along their area-weighted
    // directions
    const scalar shelteredShare = max(1 - exposedArea/area, 0);
    const scalar speed =
        Foam::sqrt(u2Area/area + shelteredShare*magSqr(Uhost));
    const vector direction
    (
        Foam::sqrt(u2Area/area)*(Uabove/magUabove) + shelteredShare*Uhost
    );
    const scalar magDirection = mag(direction);
    return magDirection > VSMALL ? speed*direction/magDirection : Uhost;
}
