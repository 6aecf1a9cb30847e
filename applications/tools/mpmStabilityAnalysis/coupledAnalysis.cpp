// mpmStabilityAnalysis --model coupled: spectral radius of the coupled step
// against kh, stability limits in one parameter, and maps of the stable
// region over (Dt/tau_p, aS) (docs/stabilityAnalysis.md, "Coupled analysis").
#include "coupledAnalysis.hpp"
#include "cliLists.hpp"
#include "stability/coupledSymbol.hpp"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using namespace mpm;
using namespace mpm::stability;
using cli::fail;
using cli::realList;
using cli::splitList;
using cli::toReal;

namespace {

constexpr Real pi = 3.14159265358979323846;

struct Range { Real lo = 0, hi = 0; int n = 0; };

struct CoupledOptions
{
    CoupledSetup base;
    std::vector<CouplingMode> modes{CouplingMode::twoWay};
    std::vector<DragVariant> variants{DragVariant::linearised};
    std::vector<Real> dtOverTau{1.0};
    Real autoSolidNumber = -1;   // --auto-sub-cycles: solid number per fluid step
    Real courant = 0.5;          // the shipped timeStep courant
    int khPerZone = 64;
    std::vector<Real> khList;
    std::string csv, limitCsv, mapCsv;
    bool table = false;
    bool limit = false;
    CoupledParameter limitParameter = CoupledParameter::dtOverTau;
    LimitOptions limitOptions;
    Range mapDt, mapAlpha;
    Real symbolKh = -1;          // --symbol: print the matrix at this kh
    Real limitKh = -1;           // --limit-kh: the limit of this kh only
};

void usage()
{
    std::printf(
"Usage: mpmStabilityAnalysis --model coupled [options]\n"
"The coupled MPM-fluid step, 1D periodic, linearised about rest, h = 1, fluid step Dt = 1.\n"
"Solid:\n"
"  --solid diffusion|wave        stress-free grains: diffusion with --number 0 (default)\n"
"  --shape LH|QBS|CBS  --alpha a  --offsets o1,o2  --scheme USL|USF|MUSL\n"
"  --number x                    Fo or CFL of one MPM sub-step (default 0)\n"
"  --sub-cycles n                MPM sub-steps per fluid step (default 1)\n"
"  --auto-sub-cycles C [--courant 0.5]\n"
"                                the shipped rule: C = solid CFL (or Fo) per fluid step,\n"
"                                n = ceil(C/courant), number = C/n\n"
"Coupling:\n"
"  --mode oneWay,twoWayMomentum,twoWay   (list; default twoWay)\n"
"  --variant explicit,frozen,linearised  (list; default linearised, the product's scheme)\n"
"  --forces drag[,pressureGradient]      (default drag,pressureGradient)\n"
"  --dt-tau d1,d2                Dt/tau_p, tau_p = aS rho_s/beta (list; default 1)\n"
"  --aS a                        solid fraction (default 0.3)\n"
"  --density-ratio r             rho_f/rho_s (default 0.4)\n"
"  --viscous x                   nu Dt/h^2 of the fluid (default 0)\n"
"  --correctors n                PIMPLE nCorrectors (default 3); --no-predictor\n"
"  --ddt-coeff x                 ddtCorr coupling coefficient (default 1, the linear limit)\n"
"Advisor (physical parameters, for parameter studies; adviseCoupledCase.py reads them from a case;\n"
"  a case's advice is mpmAdviseTimeStep <case>, the solver's own set-up):\n"
"  --advise --law L --law-coeffs k=v,.. --drag D --drag-coeffs d=..,.. --rho-f --nu-f\n"
"        --h --fluid-dt --aS [--courant 0.5 --shape --alpha --scheme --mode --forces --correctors]\n"
"        (the same advice mpmFoam prints at start-up with coupling { timeStepAdvice yes; })\n"
"Outputs:\n"
"  --nk 64 | --kh k1,k2          spectral radius vs kh (table of pi/8 multiples, or the given kh)\n"
"  --csv file                    rho(kh) of every combination\n"
"  --limit dtOverTau|alphaS|number|densityRatio|viscousNumber [--max-number x]\n"
"        [--theta-intervals n]   largest stable value (scan + bisection), every combination\n"
"  --limit-csv file  --limit-kh kh (the limit of this kh only, e.g. a run's mode)\n"
"  --symbol kh                   print the amplification matrix at kh (state v_p.., [s_p..], U, phi, p;\n"
"                                one row per line, re im pairs; first combination)\n"
"  --map-dt-tau lo:hi:n --map-aS lo:hi:n --map-csv file\n"
"                                max rho over kh on a log Dt/tau x linear aS grid\n"
"                                (plot: plotCoupledMap.py file out.png)\n");
}

Range parseRange(const std::string& s)
{
    const auto parts = splitList(s, ':');
    if (parts.size() != 3) fail("a range is lo:hi:n, got '" + s + "'");
    Range r{toReal(parts[0]), toReal(parts[1]), int(toReal(parts[2]))};
    if (!(r.hi > r.lo) || r.n < 2) fail("a range needs hi > lo and n >= 2: '" + s + "'");
    return r;
}

CoupledOptions parse(int argc, char** argv)
{
    CoupledOptions o;
    o.base.solid.model = Model::diffusion;
    o.limitOptions.maxNumber = 100;
    o.limitOptions.thetaIntervals = 90;
    o.limitOptions.scanPoints = 200;
    bool maxSet = false;
    cli::Arguments args(argc, argv, usage);
    while (args.next())
    {
        const std::string& a = args.option();
        const auto next = [&args]() { return args.value(); };
        if (a == "--model") next();
        else if (a == "--solid") { if (!parseModel(next(), o.base.solid.model)) fail("unknown solid model (diffusion wave)"); }
        else if (a == "--shape") { const std::string n = next(); if (!parseShape(n, o.base.solid.shape)) fail("unknown shape " + n + "; valid: " + validShapeNames()); }
        else if (a == "--alpha") o.base.solid.alpha = toReal(next());
        else if (a == "--offsets") o.base.solid.offsets = realList(next());
        else if (a == "--scheme") { if (!parseStressUpdate(next(), o.base.solid.scheme)) fail("unknown scheme (USL USF MUSL)"); }
        else if (a == "--number") o.base.solidNumber = toReal(next());
        else if (a == "--sub-cycles") o.base.subCycles = int(toReal(next()));
        else if (a == "--auto-sub-cycles") o.autoSolidNumber = toReal(next());
        else if (a == "--courant") o.courant = toReal(next());
        else if (a == "--mode")
        {
            o.modes.clear();
            for (const auto& n : splitList(next()))
            {
                CouplingMode m;
                if (!parseCouplingMode(n, m)) fail("unknown mode " + n + "; valid: oneWay twoWayMomentum twoWay");
                o.modes.push_back(m);
            }
        }
        else if (a == "--variant")
        {
            o.variants.clear();
            for (const auto& n : splitList(next()))
            {
                DragVariant v;
                if (!parseDragVariant(n, v)) fail("unknown variant " + n + "; valid: explicit frozen linearised");
                o.variants.push_back(v);
            }
        }
        else if (a == "--forces")
        {
            o.base.pressureGradient = false;
            bool drag = false;
            for (const auto& n : splitList(next()))
            {
                if (n == "drag") drag = true;
                else if (n == "pressureGradient") o.base.pressureGradient = true;
                else fail("unknown force " + n + "; valid: drag pressureGradient (gravity: not in the linearisation about rest)");
            }
            if (!drag) fail("--forces must list drag");
        }
        else if (a == "--dt-tau") o.dtOverTau = realList(next());
        else if (a == "--aS") o.base.alphaS = toReal(next());
        else if (a == "--density-ratio") o.base.densityRatio = toReal(next());
        else if (a == "--viscous") o.base.viscousNumber = toReal(next());
        else if (a == "--correctors") o.base.pisoCorrectors = int(toReal(next()));
        else if (a == "--ddt-coeff") o.base.ddtCorrCoefficient = toReal(next());
        else if (a == "--no-predictor") o.base.momentumPredictor = false;
        else if (a == "--nk") { o.khPerZone = int(toReal(next())); o.table = true; }
        else if (a == "--kh") { o.khList = realList(next()); o.table = true; }
        else if (a == "--csv") { o.csv = next(); o.table = true; }
        else if (a == "--limit")
        {
            const std::string n = next();
            if (!parseParameter(n, o.limitParameter))
                fail("unknown parameter " + n + "; valid: dtOverTau alphaS number densityRatio viscousNumber");
            o.limit = true;
        }
        else if (a == "--limit-csv") o.limitCsv = next();
        else if (a == "--limit-kh") o.limitKh = toReal(next());
        else if (a == "--max-number") { o.limitOptions.maxNumber = toReal(next()); maxSet = true; }
        else if (a == "--theta-intervals") o.limitOptions.thetaIntervals = int(toReal(next()));
        else if (a == "--symbol") o.symbolKh = toReal(next());
        else if (a == "--map-dt-tau") o.mapDt = parseRange(next());
        else if (a == "--map-aS") o.mapAlpha = parseRange(next());
        else if (a == "--map-csv") o.mapCsv = next();
        else fail("unknown option " + a + " (see --model coupled --help)");
    }
    CoupledSetup& b = o.base;
    if (!(b.alphaS > 0 && b.alphaS < 1)) fail("--aS must lie in (0,1)");
    if (!(b.densityRatio > 0)) fail("--density-ratio must be > 0");
    if (b.subCycles < 1) fail("--sub-cycles must be >= 1");
    if (b.pisoCorrectors < 1) fail("--correctors must be >= 1");
    for (Real d : o.dtOverTau) if (!(d >= 0)) fail("--dt-tau values must be >= 0");
    for (Real off : b.solid.offsets) if (off < 0 || off >= 1) fail("offsets must lie in [0,1)");
    if (o.autoSolidNumber >= 0)
    {
        if (!(o.courant > 0)) fail("--courant must be > 0");
        b.subCycles = std::max(1, int(std::ceil(o.autoSolidNumber/o.courant - 1e-9)));
        b.solidNumber = o.autoSolidNumber/b.subCycles;
    }
    if (o.limitParameter == CoupledParameter::alphaS && !maxSet) o.limitOptions.maxNumber = 0.99;
    if ((o.mapDt.n > 0) != (o.mapAlpha.n > 0)) fail("a map needs both --map-dt-tau and --map-aS");
    if (o.mapDt.n > 0 && !(o.mapDt.lo > 0)) fail("--map-dt-tau is logarithmic: lo must be > 0");
    if (o.mapAlpha.n > 0 && !(o.mapAlpha.lo > 0 && o.mapAlpha.hi < 1)) fail("--map-aS must lie in (0,1)");
    return o;
}

std::vector<CoupledSetup> combinations(const CoupledOptions& o, bool withDt)
{
    std::vector<CoupledSetup> out;
    for (CouplingMode m : o.modes)
        for (DragVariant v : o.variants)
        {
            CoupledSetup c = o.base;
            c.mode = m;
            c.variant = v;
            if (!withDt) { out.push_back(c); continue; }
            for (Real d : o.dtOverTau) { c.dtOverTau = d; out.push_back(c); }
        }
    return out;
}

std::string fields(const CoupledSetup& c)
{
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s,%s,%d,%.17g,%.17g,%d,%.17g,%.17g,%s,%s,%.17g",
                  couplingModeName(c.mode), dragVariantName(c.variant), int(c.pressureGradient),
                  c.alphaS, c.densityRatio, c.subCycles, c.solidNumber, c.viscousNumber,
                  modelName(c.solid.model), shapeShortName(c.solid.shape), c.solid.alpha);
    return buf;
}
const char* fieldNames = "mode,variant,pressureGradient,alphaS,densityRatio,subCycles,number,viscousNumber,solid,shape,alpha";

void printSymbol(const CoupledOptions& o)
{
    const CoupledSetup c = combinations(o, true).front();
    const ComplexMatrix A = coupledSymbol(c, o.symbolKh);
    std::printf("# %s\n# kh %.17g, %d x %d\n", describe(c).c_str(), o.symbolKh, A.rows, A.cols);
    for (int r = 0; r < A.rows; ++r)
    {
        for (int k = 0; k < A.cols; ++k) std::printf("%s%.17g %.17g", k ? " " : "", A(r, k).real(), A(r, k).imag());
        std::printf("\n");
    }
}

void runTable(const CoupledOptions& o)
{
    std::ofstream csv;
    if (!o.csv.empty())
    {
        csv.open(o.csv);
        if (!csv) fail("cannot write " + o.csv);
        csv << fieldNames << ",dtOverTau,kh,spectralRadius\n";
        csv.precision(16);
    }
    for (const CoupledSetup& c : combinations(o, true))
    {
        std::printf("\n== %s\n%10s %14s\n", describe(c).c_str(), "kh/pi", "rho(A)");
        std::vector<std::pair<Real, bool>> khs;
        if (!o.khList.empty()) for (Real kh : o.khList) khs.emplace_back(kh, true);
        else for (int i = 1; i <= o.khPerZone; ++i) khs.emplace_back(pi*i/o.khPerZone, (8*i) % o.khPerZone == 0);
        for (const auto& [kh, print] : khs)
        {
            if (!(kh > 0 && kh <= pi + 1e-12)) fail("--kh values must lie in (0, pi] (one grid zone: a cell holds one fluid value)");
            const Real rho = coupledSpectralRadius(c, std::min(kh, pi));
            if (print) std::printf("%10.4f %14.8f\n", kh/pi, rho);
            if (csv) csv << fields(c) << ',' << c.dtOverTau << ',' << kh << ',' << rho << '\n';
        }
    }
    if (csv) std::printf("\nwrote %s\n", o.csv.c_str());
}

void runLimits(const CoupledOptions& o)
{
    std::ofstream csv;
    if (!o.limitCsv.empty())
    {
        csv.open(o.limitCsv);
        if (!csv) fail("cannot write " + o.limitCsv);
        csv << fieldNames << ",dtOverTau,parameter,limit,reachedMax\n";
        csv.precision(16);
    }
    const bool inDt = o.limitParameter == CoupledParameter::dtOverTau;
    if (o.limitKh > 0)
        std::printf("\nStability limits in %s (rho(kh = %.17g) <= 1 + %g, searched in (0, %g])\n",
                    parameterName(o.limitParameter), o.limitKh, o.limitOptions.slack, o.limitOptions.maxNumber);
    else
        std::printf("\nStability limits in %s (max over kh = pi j/%d of rho <= 1 + %g, searched in (0, %g])\n",
                    parameterName(o.limitParameter), o.limitOptions.thetaIntervals, o.limitOptions.slack,
                    o.limitOptions.maxNumber);
    for (const CoupledSetup& c : combinations(o, !inDt))
    {
        const StabilityLimit L = o.limitKh > 0
            ? stabilityLimit([&](Real x) {
                  CoupledSetup t = c;
                  setParameter(t, o.limitParameter, x);
                  return coupledSpectralRadius(t, o.limitKh) <= 1 + o.limitOptions.slack;
              }, o.limitOptions)
            : coupledStabilityLimit(c, o.limitParameter, o.limitOptions);
        std::printf("%-15s %-11s %s limit %s%.12g\n", couplingModeName(c.mode), dragVariantName(c.variant),
                    inDt ? "" : ("Dt/tau=" + std::to_string(c.dtOverTau)).c_str(),
                    L.reachedMax ? ">= " : "", L.limit);
        if (csv) csv << fields(c) << ',' << (inDt ? -1.0 : c.dtOverTau) << ',' << parameterName(o.limitParameter)
                     << ',' << L.limit << ',' << int(L.reachedMax) << '\n';
    }
    if (csv) std::printf("wrote %s\n", o.limitCsv.c_str());
}

void runMap(const CoupledOptions& o)
{
    std::ofstream csv;
    if (!o.mapCsv.empty())
    {
        csv.open(o.mapCsv);
        if (!csv) fail("cannot write " + o.mapCsv);
        csv << fieldNames << ",dtOverTau,maxSpectralRadius\n";
        csv.precision(16);
    }
    std::printf("\nMap of max rho over kh: Dt/tau in [%g, %g] (log, %d), aS in [%g, %g] (%d)\n",
                o.mapDt.lo, o.mapDt.hi, o.mapDt.n, o.mapAlpha.lo, o.mapAlpha.hi, o.mapAlpha.n);
    for (CoupledSetup c : combinations(o, false))
    {
        int unstable = 0;
        Real worst = 0;
        for (int i = 0; i < o.mapAlpha.n; ++i)
            for (int j = 0; j < o.mapDt.n; ++j)
            {
                c.alphaS = o.mapAlpha.lo + (o.mapAlpha.hi - o.mapAlpha.lo)*i/(o.mapAlpha.n - 1);
                c.dtOverTau = o.mapDt.lo*std::pow(o.mapDt.hi/o.mapDt.lo, Real(j)/(o.mapDt.n - 1));
                const Real rho = coupledMaxSpectralRadius(c, o.limitOptions.thetaIntervals);
                unstable += rho > 1 + o.limitOptions.slack;
                worst = std::max(worst, rho);
                if (csv) csv << fields(c) << ',' << c.dtOverTau << ',' << rho << '\n';
            }
        std::printf("%-15s %-11s unstable points %d of %d, largest rho %.6g\n", couplingModeName(c.mode),
                    dragVariantName(c.variant), unstable, o.mapAlpha.n*o.mapDt.n, worst);
    }
    if (csv) std::printf("wrote %s\n", o.mapCsv.c_str());
}

} // namespace

int runCoupled(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i) if (std::string(argv[i]) == "--advise") return runAdvisor(argc, argv);
    const CoupledOptions o = parse(argc, argv);
    if (!o.table && !o.limit && o.mapDt.n == 0 && o.symbolKh < 0)
    {
        usage();
        std::fprintf(stderr, "\nnothing to do: give --nk/--kh/--csv, --limit or a map\n");
        return 1;
    }
    try
    {
        if (o.symbolKh >= 0) printSymbol(o);
        if (o.table) runTable(o);
        if (o.limit) runLimits(o);
        if (o.mapDt.n > 0) runMap(o);
    }
    catch (const std::exception& e)
    {
        fail(e.what());
    }
    return 0;
}
