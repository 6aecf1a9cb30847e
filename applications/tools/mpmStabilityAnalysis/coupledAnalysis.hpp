// mpmStabilityAnalysis --model coupled: the spectral analysis of the coupled
// MPM-fluid step (src/mpmCore/stability/coupledSymbol.hpp).
#pragma once

int runCoupled(int argc, char** argv);
// --model coupled --advise: a case's physical parameters (coupledAdvisor.cpp)
int runAdvisor(int argc, char** argv);
