# interDemFoam test suite, read by ctest directly (no CMake step):
#     cd tests && ctest            (tests/Alltest builds first, then does this)
#     ctest -L unit | -L case | -L build
# Case tests run in tests/run/<name>; a skipped test exits 77.

add_test(unit.setupMesh "bash" "unit/setupMesh.sh")
set_tests_properties(unit.setupMesh PROPERTIES
    LABELS "unit" FIXTURES_SETUP unitMesh)

add_test(unit.demCoupling "demCouplingTests" "-case" "run/meshCase")
set_tests_properties(unit.demCoupling PROPERTIES
    LABELS "unit" FIXTURES_REQUIRED unitMesh TIMEOUT 120)

# The unit tests' negative control: one test made to fail
# (DEMCOUPLING_TESTS_FAIL) must make the binary exit non-zero, or a failing
# unit test would pass in ctest (it did: OpenFOAM's argList ends with exit 0)
add_test(unit.failureReported "env" "DEMCOUPLING_TESTS_FAIL=1" "demCouplingTests"
    "--gtest_filter=harness.*" "-case" "run/meshCase")
set_tests_properties(unit.failureReported PROPERTIES
    LABELS "unit" FIXTURES_REQUIRED unitMesh WILL_FAIL TRUE TIMEOUT 60)

add_test(case.closedBoxSerial "bash" "cases/closedBoxConservation.sh" "serial")
set_tests_properties(case.closedBoxSerial PROPERTIES LABELS "case" TIMEOUT 600)

add_test(case.closedBoxParallel "bash" "cases/closedBoxConservation.sh" "parallel")
set_tests_properties(case.closedBoxParallel PROPERTIES LABELS "case;parallel" TIMEOUT 600)

add_test(case.badAlphaControls "bash" "cases/badAlphaControls.sh")
set_tests_properties(case.badAlphaControls PROPERTIES LABELS "case;input" TIMEOUT 300)

# Turbulence with eps over and in a fixed bed: k damped inside the bed, the
# log law and the grains' stress above it (interDemFoam, pimpleDemFoam)
add_test(case.turbulentBed "bash" "cases/turbulentBed.sh")
set_tests_properties(case.turbulentBed PROPERTIES LABELS "case;coupled;erosion" TIMEOUT 1200)

# The library's floors: no include runs back up (bin/includeLayers)
add_test(build.includeLayers "bash" "cases/includeLayers.sh")
set_tests_properties(build.includeLayers PROPERTIES LABELS "build" TIMEOUT 60)

add_test(build.allwmakeOffline "bash" "cases/allwmakeOffline.sh")
set_tests_properties(build.allwmakeOffline PROPERTIES
    LABELS "build;input" TIMEOUT 300 SKIP_RETURN_CODE 77)

# Coupled to LIGGGHTS: one particle from air into water (seed Table 1)
# against the seed's eq. 19, serial, on 2 ranks, with adjustTimeStep, and
# with explicit momentum coupling
add_test(case.settlingSerial "bash" "cases/singleParticleSettling.sh" "serial")
set_tests_properties(case.settlingSerial PROPERTIES LABELS "case;coupled" TIMEOUT 600)

add_test(case.settlingParallel "bash" "cases/singleParticleSettling.sh" "parallel")
set_tests_properties(case.settlingParallel PROPERTIES LABELS "case;coupled;parallel" TIMEOUT 600)

add_test(case.settlingAdjustable "bash" "cases/singleParticleSettling.sh" "adjustable")
set_tests_properties(case.settlingAdjustable PROPERTIES LABELS "case;coupled" TIMEOUT 600)

add_test(case.settlingExplicit "bash" "cases/singleParticleSettling.sh" "explicit")
set_tests_properties(case.settlingExplicit PROPERTIES LABELS "case;coupled" TIMEOUT 600)

add_test(case.couplingInputErrors "bash" "cases/couplingInputErrors.sh")
set_tests_properties(case.couplingInputErrors PROPERTIES LABELS "case;coupled;input" TIMEOUT 600)

# No input makes the solver crash: 94 mutations of a small coupled case,
# each ends with exit 0 or a clear error (never a signal, hang or silent
# abort), as the mutation list says
add_test(case.inputFuzz "bash" "cases/inputFuzz.sh")
set_tests_properties(case.inputFuzz PROPERTIES LABELS "case;coupled;input" TIMEOUT 900)

# The voidfraction field of a cell-sized particle bed split by METIS: 2 ranks
# = serial, particle volume conserved (centre, divided, virtualSphere)
add_test(case.voidFractionParallel "bash" "cases/voidFractionParallel.sh")
set_tests_properties(case.voidFractionParallel PROPERTIES LABELS "case;coupled;parallel" TIMEOUT 600)

# Fixed packed bed: pressure gradient within 10 % of Ergun (Gidaspow, Rong)
add_test(case.packedBedGidaspow "bash" "cases/packedBed.sh" "GidaspowDrag")
set_tests_properties(case.packedBedGidaspow PROPERTIES LABELS "case;coupled;forces" TIMEOUT 600)

add_test(case.packedBedRong "bash" "cases/packedBed.sh" "RongDrag")
set_tests_properties(case.packedBedRong PROPERTIES LABELS "case;coupled;forces" TIMEOUT 600)

# The single-phase solver (pimpleDemFoam) on the same bed: Ergun within 10 %,
# interDemFoam's pressure gradient within 0.1 %, continuity as good as interDemFoam's; its
# negative control (no drag) must miss Ergun by more than 50 %
add_test(case.packedBedSinglePhase "bash" "cases/packedBed.sh" "RongDrag" "pimpleDemFoam")
set_tests_properties(case.packedBedSinglePhase PROPERTIES LABELS "case;coupled;forces" TIMEOUT 600)

# Released bed above minimum fluidization: alpha stays 1 while eps changes
add_test(case.fluidizedBedAlpha "bash" "cases/packedBed.sh" "fluidize")
set_tests_properties(case.fluidizedBedAlpha PROPERTIES LABELS "case;coupled" TIMEOUT 600)

# interFoam parity: semi-implicit MULES and sub-cycles carry eps (alpha = 1
# kept, water conserved with particles moving, settling as in eq. 19), and
# OpenFOAM's own damBreak runs unchanged with interDemFoam as with interFoam
add_test(case.fluidizedBedSubCycled "bash" "cases/packedBed.sh" "fluidizeSubCycled")
set_tests_properties(case.fluidizedBedSubCycled PROPERTIES LABELS "case;coupled;alpha" TIMEOUT 600)
# the continuity correction by PCG with the envelopeCholesky preconditioner
# (the Laplacian's exact factor): the same alpha and water checks, one
# iteration per solve, one factorisation per run
add_test(case.fluidizedBedEnvelopeCholesky "bash" "cases/packedBed.sh" "fluidizeEnvelopeCholesky")
set_tests_properties(case.fluidizedBedEnvelopeCholesky PROPERTIES LABELS "case;coupled;alpha" TIMEOUT 600)
add_test(case.settlingSubCycled "bash" "cases/singleParticleSettling.sh" "subCycled")
set_tests_properties(case.settlingSubCycled PROPERTIES LABELS "case;coupled;alpha" TIMEOUT 600)
add_test(case.closedBoxSubCycled "bash" "cases/closedBoxConservation.sh" "subCycled")
set_tests_properties(case.closedBoxSubCycled PROPERTIES LABELS "case;alpha" TIMEOUT 600)
add_test(case.interFoamParity "bash" "cases/interFoamParity.sh")
set_tests_properties(case.interFoamParity PROPERTIES LABELS "case;alpha" TIMEOUT 600)

# Restart: killed with SIGKILL, restarted from latestTime, same end state as
# an uninterrupted run; a packing at rest stays at rest across a restart
add_test(case.restart "bash" "cases/restart.sh")
set_tests_properties(case.restart PROPERTIES LABELS "case;coupled;reliability" TIMEOUT 600)

# Landslide dam breach, tiny: pour, overtop, erode, analyse; water balance 1 %
add_test(case.damBreach "bash" "cases/damBreach.sh")
set_tests_properties(case.damBreach PROPERTIES LABELS "case;coupled;damBreach" TIMEOUT 900)

# allReduce and manyToMany particle exchanges: the same fields, forces and
# DEM state on 2 ranks to all digits, on 3 and 4 ranks to 1e-12; held counts
add_test(case.exchangeIdentical "bash" "cases/exchangeIdentical.sh")
set_tests_properties(case.exchangeIdentical PROPERTIES LABELS "case;coupled;parallel" TIMEOUT 600)

# Pictures: one ParaView frame of a 3-step coupled run (20 particles) shows
# the particles (warm pixels > 2 %); with the cloud removed the check fails
add_test(case.render "bash" "cases/render.sh")
set_tests_properties(case.render PROPERTIES LABELS "case;render" TIMEOUT 300 SKIP_RETURN_CODE 77)

# Damaged DEM restart files, serial and on 2 ranks: a truncated file (and
# the same file read by LIGGGHTS: the output guard), a kill while the file is
# written, a full disk (tmpfs; skipped without root). Each stops within 30 s
# with < 10 MB of output and restarts with -restartFromLastComplete.
add_test(case.restartTruncated "bash" "cases/restartDamaged.sh" "truncated")
set_tests_properties(case.restartTruncated PROPERTIES LABELS "case;coupled;reliability" TIMEOUT 600)

add_test(case.restartKilled "bash" "cases/restartDamaged.sh" "killed")
set_tests_properties(case.restartKilled PROPERTIES LABELS "case;coupled;reliability" TIMEOUT 600)

add_test(case.restartDiskFull "bash" "cases/restartDamaged.sh" "diskFull")
set_tests_properties(case.restartDiskFull PROPERTIES
    LABELS "case;coupled;reliability" TIMEOUT 600 SKIP_RETURN_CODE 77)

# A particle straddling a cyclic patch: virtualSphere and divided put the
# same eps on both sides as the same particle in a larger box, serial and on
# 2 ranks with the cyclic pair split between them
add_test(case.periodicVoidFraction "bash" "cases/periodicVoidFraction.sh")
set_tests_properties(case.periodicVoidFraction PROPERTIES LABELS "case;coupled;parallel" TIMEOUT 600)

# Physics against references (issue 16): the seed's settling particle with
# cells as large as it (virtualSphere within 1.5 % of eq. 19 at dx/d = 1, 2;
# centre at dx/d = 1 must be worse), minimum fluidization against Wen-Yu
# (20 %; Schiller-Naumann must miss), Saffman and Magnus lift on a held
# particle against eqs. 15-16 (2 %; reversed lag or spin must flip them)
add_test(case.cellSizeSettling "bash" "cases/cellSizeSettling.sh")
set_tests_properties(case.cellSizeSettling PROPERTIES LABELS "case;coupled;voidFraction" TIMEOUT 300)

add_test(case.minFluidization "bash" "cases/minFluidization.sh")
set_tests_properties(case.minFluidization PROPERTIES LABELS "case;coupled;forces" TIMEOUT 300)

add_test(case.minFluidizationControl "bash" "cases/minFluidization.sh" "control")
set_tests_properties(case.minFluidizationControl PROPERTIES LABELS "case;coupled;forces" TIMEOUT 300)

add_test(case.liftSaffman "bash" "cases/liftForces.sh" "saffman")
set_tests_properties(case.liftSaffman PROPERTIES LABELS "case;coupled;forces" TIMEOUT 120)

add_test(case.liftMagnus "bash" "cases/liftForces.sh" "magnus")
set_tests_properties(case.liftMagnus PROPERTIES LABELS "case;coupled;forces" TIMEOUT 120)

add_test(case.liftWibergSmith "bash" "cases/liftForces.sh" "wibergSmith")
set_tests_properties(case.liftWibergSmith PROPERTIES LABELS "case;coupled;forces" TIMEOUT 120)

add_test(case.fluidVelocityCellPoint "bash" "cases/liftForces.sh" "sampling")
set_tests_properties(case.fluidVelocityCellPoint PROPERTIES LABELS "case;coupled;forces" TIMEOUT 180)

add_test(case.samplingParallel "bash" "cases/samplingParallel.sh")
set_tests_properties(case.samplingParallel PROPERTIES LABELS "case;coupled;parallel" TIMEOUT 400)

add_test(case.damGrading "bash" "cases/damGrading.sh")
set_tests_properties(case.damGrading PROPERTIES LABELS "case;damBreach" TIMEOUT 400)

add_test(case.breachEnded "bash" "cases/breachEnded.sh")
set_tests_properties(case.breachEnded PROPERTIES LABELS "case;damBreach" TIMEOUT 60)

add_test(case.breachResume "bash" "cases/breachResume.sh")
set_tests_properties(case.breachResume PROPERTIES LABELS "case;damBreach" TIMEOUT 60)

add_test(case.breachResumeRun "bash" "cases/breachResumeRun.sh")
set_tests_properties(case.breachResumeRun PROPERTIES LABELS "case;coupled;damBreach" TIMEOUT 900)

# Quiet dense beds: plate pressure of a bed at rest (std <= 1 % of its
# weight) and fluidized (<= 5 %); the former scheme must fail
add_test(case.quietBed "bash" "cases/quietBed.sh")
set_tests_properties(case.quietBed PROPERTIES LABELS "case;coupled;forces" TIMEOUT 600)

# Bedload (issue 20): a small periodic channel, theta 0.2 (below this
# laminar model's onset): no transport; theta 0.8: sustained transport, the
# grains carry rho g S h, q* within x2 of the model's reference (1/10 of
# Meyer-Peter-Mueller: docs/erosion.md); without fluid-particle forces
# (negative control) the transport check must fail
add_test(case.bedload "bash" "cases/bedload.sh")
set_tests_properties(case.bedload PROPERTIES LABELS "case;coupled;erosion" TIMEOUT 600)

# A graded bed in the bedload channel (issue 48, which grains move first):
# bad -grading input named, the poured classes' mass shares, theta on the
# geometric mean diameter, the classes' fluxes against LIGGGHTS's own total
# (negative control: a broken grain volume), Wilcock & Crowe's equations
add_test(case.bedloadGraded "bash" "cases/bedloadGraded.sh")
set_tests_properties(case.bedloadGraded PROPERTIES LABELS "case;coupled;erosion" TIMEOUT 300)

# The scene check before a run (checkDemScene): a measured failure region
# (centre at dx = d), a safe scene, a coupling step in explicit drag's
# blow-up region, a missing DEM script
add_test(case.checkScene "bash" "cases/checkScene.sh")
set_tests_properties(case.checkScene PROPERTIES LABELS "case;input" TIMEOUT 300)

# The DEM's processor grid chosen from the grains (bin/demGrid, the
# flagship's -demGrid auto) against LIGGGHTS's own neighbour counts
add_test(case.demGrid "bash" "cases/demGrid.sh")
set_tests_properties(case.demGrid PROPERTIES LABELS "case;parallel" TIMEOUT 300)
