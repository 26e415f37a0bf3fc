#The ctest labels of the GoogleTest tests(test / CMakeLists.txt) : every test is `fast` or `slow`,
#and `real` where it reads the real recordings in data / real /. `slow`: 3 s or more in Release on
#the 2 - core machine(ctest-- timeout - free timing, 2026 - 11 - 27); \
    the sanitizer run leaves them out.
#A test not named here is fast and not real.
set(GIOCAL_SLOW_TESTS StateFile.WrittenAsTheRunGoesReadBackAndADamagedOneStartsCold SingleReceiver
        .BothEstimatorsCalibrateAFieldDriveFromARoverAlone SingleReceiver
        .ARoverWithABaseCalibratesWithItsRoverAloneToo SingleReceiver
        .WhatTheRoverLacksIsSaidAndTheRunGoesOnWithTheRest WarmStart
        .ASecondDriveFromTheFirstsCalibrationConvergesEarlierAndEndsCloser Validate
        .ACalibrationOfASimulatedDriveIsBetterThanTheGuessInEveryWindow DegradedRuns
        .BothEstimatorsStayConsistentUnderWheelSlipOverTenSeeds OnlineCalibrator
        .TheOdometerDelayIsEstimatedByBothEstimators ImuGaps
        .BothEstimatorsBridgeOrRestartAndStayWithinTwiceTheCleanError OnlineCalibrator
        .TheGyroTiltIsEstimatedByBothEstimators RealHusky
        .LooselyCoupledCalibrationAndDeadReckoningFromItsGnssFixes RealHusky
        .DefaultsWeighTheWanderingHeightsByWhatTheDriveShows DegradedRuns
        .BothEstimatorsSayWhenTheyDivergeAndStartAgain OnlineCalibrator
        .BothEstimatorsWeighTheNonHolonomicConstraintAlike SimulateTrajectory
        .TheSimulatorsOwnGnssAndAntennaPathGiveItsDriveAndCalibration GnssSimulation
        .GiocalRtkFixesUnderTreesAreWithin5cm OnlineCalibrator
        .LateOdometerStampsAreNamedWithTheOffsetToSet DegradedRuns
        .ACalibrationThatJumpsIsNamed DegradedRuns
        .TheFactorGraphLeavesOutSlippingOdometerSamples RealHusky
        .AnOdometerDelayStateThatDisagreesWithTheYawRatesIsNamed OnlineCalibrator
        .StreamedReplayEqualsTheBatchCalibrators OdometerDelay
        .LateAndEarlyWheelStampsOfSimulatedDrives CoarseMounting
        .SimulatedDrivesWithTheImuFarOff I2navImport
        .ASimulatedDriveRoundTripsAndCalibratesWithItsSpeedOnlyOdometer LooselyCoupled
        .BothEstimatorsCalibrateFromRtkPositionsThroughTheLeverArm LooselyCoupled
        .BothEstimatorsAreConsistentOverTenSeeds RealMovedRover
        .MosaicRoverMovedAlongTwoFieldLapsFixesAndCalibrates RealMovedRover
        .TheSameRoverAloneCalibratesFromItsTimeDifferencedPhase SparseGnss
        .AFloatFirstEpochIsNotHeldAsFixed RealMovedRover
        .GsiTrimbleRoverMovedAlongTheFieldDriveFixesAndCalibrates)
    set(GIOCAL_REAL_TESTS PhaseAlignment
            .TheRealFilesAreAlignedOrRepairedWhereTheyAreNot BroadcastOrbitsHealth
            .QzssLastBitIsMaskedAnyOtherBitExcludes Tdcp.TheRowsGradientsAreTheNumericOnes Tdcp
            .ADisplacementThroughAClockStepASlipAndAHalfCycleIsRecovered Tdcp
            .StaticRoversOfTheRealPairsStayPutAsSingleReceivers Tdcp
            .ASatelliteThatSlipsAtEveryEpochIsNamedOnceAndLeftOut TdcpWalk
            .DisplacementsPerEpochAgreeWithRtklibsFixedSolution Rtk
            .MixedReceivers5kmFixesEveryEpoch BagImport
            .GnssCommMessagesRoundTripARealReceiversObservations BagImport
            .RealHuskyAndJackalBags BagImport.UbloxRawGnssReadsAsTheUbxLogDoes CoarseMounting
            .RealHuskyLog CycleSlip.ACodeOutlierIsNotASlipWhenThePhaseTestsPass CycleSlip
            .ASignalBlockedForAMomentIsTestedAcrossTheGap CycleSlip
            .FewFalseAlarmsOnRealDataAndInjectedSlipsAreFound Ephemeris
            .VelocityAndClockDriftAreTheDerivativesOfPositionAndClock PosFile
            .ReadsRtklibsAndItsOwnSolutionsWithTheirCovariances RealMovedRover
            .MosaicRoverMovedAlongTwoFieldLapsFixesAndCalibrates RealMovedRover
            .TheSameRoverAloneCalibratesFromItsTimeDifferencedPhase RealMovedRover
            .GsiTrimbleRoverMovedAlongTheFieldDriveFixesAndCalibrates RealHusky
            .AnOdometerDelayStateThatDisagreesWithTheYawRatesIsNamed RealHusky
            .DefaultsWeighTheWanderingHeightsByWhatTheDriveShows RealHusky
            .HeightsLeftOutByHandAreNotChecked RealHusky
            .LooselyCoupledCalibrationAndDeadReckoningFromItsGnssFixes RinexObs
            .EventFlagRecordsAreSkipped Rtk.BadInputIsReported Rtk.GsiRinex2MatchesRtklib Rtk
            .MosaicGpsOnly Rtk.MosaicMultiGnssFixesAndHitsTheKnownPosition Rtk
            .MosaicThreeFrequencies SimConfig.ManyLapsReadFast Spp.GsiRinex2WithinFiveMetres Spp
            .MosaicGpsOnly Spp.MosaicMultiConstellationWithinFiveMetresAndStaticDoppler UbxLog
            .ADamagedCopyIsReadUpToTheDamageAndSaysWhere UbxRealLog
            .BeidouD1EphemeridesAgreeWithConvbin UbxRealLog
            .BeidouD2EphemerisAgreesWithConvbin UbxRealLog
            .EveryObservationAgreesWithConvbin UbxRealLog
            .GalileoEphemeridesPositionTheReceiverAsGpsDoes UbxRealLog
            .GpsEphemeridesAgreeWithConvbin)
#Tests that assert an open issue's target the data do not reach yet: ctest runs them with
#WILL_FAIL under the label `real_open` (test / CMakeLists.txt), \
    so each reports the day its target is
#met(then it moves to the lists above) instead of being loosened to pass.
        set(GIOCAL_OPEN_TARGET_TESTS RealHusky
                .OpenTargetBothValidateBetterAndAgreeWithinThreeSigmas)
