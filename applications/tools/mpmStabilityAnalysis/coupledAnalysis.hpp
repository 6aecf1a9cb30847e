// mpmStabilityAnalysis --model coupled: the spectral analysis of the coupled
// MPM-fluid step (src/mpmCore/stability/coupledSymbol.hpp).
#pragma once

int runCoupled(int argc, char** argv);
