// mpmStabilityAnalysis --model coupled --advise: the coupled analysis in a
// case's physical parameters, for parameter studies (adviseCoupledCase.py
// reads them from the dictionaries, with an override; a case's advice is
// the solver's, mpmAdviseTimeStep <case>). The advice itself is the core's (stability/coupledAdvice,
// which the solver prints at start-up too): this file reads the options and
// makes the laws by name. Prints the MPM step (with the pure-MPM limit and
// its margin), the sub-cycles, max |G| of each variant at the case's step,
// and the largest fluid step the product's scheme keeps stable (scanned up
// to 8x).
#include "coupledAnalysis.hpp"
#include "cliLists.hpp"
#include "constitutive/constitutiveLaw.hpp"
#include "drag/dragLaw.hpp"
#include "stability/coupledAdvice.hpp"
#include <cstdio>
#include <string>

using namespace mpm;
using namespace mpm::stability;
using cli::fail;
using cli::splitList;
using cli::toReal;

namespace {

Coefficients coefficients(const std::string& s)
{
    Coefficients c;
    for (const std::string& kv : splitList(s))
    {
        const auto eq = kv.find('=');
        if (eq == std::string::npos) fail("coefficients are key=value, got '" + kv + "'");
        c[kv.substr(0, eq)] = toReal(kv.substr(eq + 1));
    }
    return c;
}

} // namespace

int runAdvisor(int argc, char** argv)
{
    CoupledCase cc;
    CoupledSetup& base = cc.base;
    base.solid.offsets = {0.5};
    cc.lawName = "dilute";
    cc.dragName = "Ergun";
    Coefficients lawCoeffs, dragCoeffs;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) fail("missing value after " + a);
            return argv[++i];
        };
        if (a == "--model" || a == "--advise") { if (a == "--model") next(); }
        else if (a == "--law") cc.lawName = next();
        else if (a == "--law-coeffs") lawCoeffs = coefficients(next());
        else if (a == "--drag") cc.dragName = next();
        else if (a == "--drag-coeffs") dragCoeffs = coefficients(next());
        else if (a == "--rho-f") cc.rhoF = toReal(next());
        else if (a == "--nu-f") cc.nuF = toReal(next());
        else if (a == "--h") cc.h = toReal(next());
        else if (a == "--fluid-dt") cc.dt = toReal(next());
        else if (a == "--courant") cc.courant = toReal(next());
        else if (a == "--aS") base.alphaS = toReal(next());
        else if (a == "--theta-intervals") cc.thetaIntervals = int(toReal(next()));
        else if (a == "--shape") { const std::string n = next(); if (!parseShape(n, base.solid.shape)) fail("unknown shape " + n); }
        else if (a == "--alpha") base.solid.alpha = toReal(next());
        else if (a == "--scheme") { if (!parseStressUpdate(next(), base.solid.scheme)) fail("unknown scheme (USL USF MUSL)"); }
        else if (a == "--mode") { if (!parseCouplingMode(next(), base.mode)) fail("unknown mode; valid: oneWay twoWayMomentum twoWay"); }
        else if (a == "--forces")
        {
            base.pressureGradient = false;
            for (const auto& f : splitList(next())) if (f == "pressureGradient") base.pressureGradient = true;
        }
        else if (a == "--correctors") base.pisoCorrectors = int(toReal(next()));
        else fail("unknown option " + a + " with --advise");
    }
    if (!(cc.h > 0) || !(cc.dt > 0)) fail("--advise needs --h and --fluid-dt > 0");
    if (!(base.alphaS > 0 && base.alphaS < 1)) fail("--aS must lie in (0,1)");
    std::unique_ptr<ConstitutiveLaw> law;
    std::unique_ptr<DragLaw> drag;
    try
    {
        law = makeLaw(cc.lawName, lawCoeffs);
        drag = makeDragLaw(cc.dragName, dragCoeffs);
    }
    catch (const std::exception& e) { fail(e.what()); }

    for (const std::string& line : adviceLines(cc, adviseCoupled(cc, *law, *drag)))
        std::printf("%s\n", line.c_str());
    return 0;
}
