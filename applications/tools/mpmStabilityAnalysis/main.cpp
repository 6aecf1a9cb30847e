// mpmStabilityAnalysis: von Neumann analysis of the 1D MPM velocity update.
//
// Every list option (--shape, --alpha, --mass, --scheme) runs the Cartesian
// product of its values, so one call produces a whole comparison; see
// --help and docs/stabilityAnalysis.md.
#include "stability/fourierSymbol.hpp"
#include "stability/stabilityLimit.hpp"
#include "cliLists.hpp"
#include "coupledAnalysis.hpp"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace mpm;
using namespace mpm::stability;

namespace {

constexpr Real pi = 3.14159265358979323846;

struct Options
{
    Model model = Model::diffusion;
    std::vector<ShapeKind> shapes{ShapeKind::linearHat};
    std::vector<Real> alphas{0.0};
    std::vector<MassMatrix> masses{MassMatrix::lumped};
    std::vector<StressUpdate> schemes{StressUpdate::USL};
    std::vector<Real> offsets{0.5};
    std::vector<Real> numbers;        // Fo or CFL values
    int khPerZone = 64;               // kh samples per grid zone (0, pi]
    std::vector<Real> khList;         // --kh: these wavenumbers instead
    std::string csv, limitCsv, sweepCsv;
    bool limit = false;
    int sweepPoints = 0;
    LimitOptions limitOptions;
    bool maxNumberSet = false;
};

void usage()
{
    std::cout <<
"Usage: mpmStabilityAnalysis [options]\n"
"  --model diffusion|wave        model problem (default diffusion)\n"
"  --model coupled ...           the coupled MPM-fluid step (see --model coupled --help)\n"
"  --shape LH,QBS,CBS            shape function(s)\n"
"  --alpha 0,0.5,1               FLIP fraction(s): 0 PIC, 1 FLIP\n"
"  --mass lumped,consistent      mass matrix kind(s)\n"
"  --scheme USL,USF,MUSL         stress update order(s) (wave only)\n"
"  --offsets 0.25,0.75           point offsets in each cell, lattice units [0,1)\n"
"  --Fo 0.1,0.5 | --CFL 0.5,1    parameter values for the G(kh) table/CSV\n"
"  --nk 64                       kh samples per grid zone (0,pi]\n"
"  --kh 0.126,0.628              these kh only (instead of --nk), every one printed\n"
"  --csv file                    write G(kh) for every combination\n"
"  --limit                       compute the stability limit of every combination\n"
"  --limit-csv file              write the limits\n"
"  --sweep-offsets n [--sweep-csv file]\n"
"                                limit vs shift s=(i+0.5)/n of the offset pattern\n"
"                                (use --offsets 0 for limit vs single-point offset)\n"
"  --max-number x                limit search range (0,x] (default 8 Fo, 4 CFL)\n"
"  --theta-intervals n           kh samples in [0,pi] for the limit (default 360)\n";
}

using cli::fail;
using cli::realList;
using cli::splitList;

Options parse(int argc, char** argv)
{
    Options o;
    cli::Arguments args(argc, argv, usage);
    while (args.next())
    {
        const std::string& a = args.option();
        const auto next = [&args]() { return args.value(); };
        if (a == "--model") { if (!parseModel(next(), o.model)) fail("unknown model"); }
        else if (a == "--shape")
        {
            o.shapes.clear();
            for (const std::string& n : splitList(next()))
            {
                ShapeKind k;
                if (!parseShape(n, k)) fail("unknown shape " + n + "; valid: " + validShapeNames());
                o.shapes.push_back(k);
            }
        }
        else if (a == "--alpha") o.alphas = realList(next());
        else if (a == "--mass")
        {
            o.masses.clear();
            for (const std::string& n : splitList(next()))
            {
                MassMatrix m;
                if (!parseMassMatrix(n, m)) fail("unknown mass " + n);
                o.masses.push_back(m);
            }
        }
        else if (a == "--scheme")
        {
            o.schemes.clear();
            for (const std::string& n : splitList(next()))
            {
                StressUpdate s;
                if (!parseStressUpdate(n, s)) fail("unknown scheme " + n);
                o.schemes.push_back(s);
            }
        }
        else if (a == "--offsets") o.offsets = realList(next());
        else if (a == "--Fo" || a == "--CFL") o.numbers = realList(next());
        else if (a == "--nk") o.khPerZone = std::stoi(next());
        else if (a == "--kh")
        {
            o.khList = realList(next());
            for (Real kh : o.khList) if (!(kh > 0)) fail("--kh values must be > 0");
        }
        else if (a == "--csv") o.csv = next();
        else if (a == "--limit") o.limit = true;
        else if (a == "--limit-csv") { o.limitCsv = next(); o.limit = true; }
        else if (a == "--sweep-offsets") o.sweepPoints = std::stoi(next());
        else if (a == "--sweep-csv") o.sweepCsv = next();
        else if (a == "--max-number") { o.limitOptions.maxNumber = std::stod(next()); o.maxNumberSet = true; }
        else if (a == "--theta-intervals") o.limitOptions.thetaIntervals = std::stoi(next());
        else fail("unknown option " + a + " (see --help)");
    }
    for (Real off : o.offsets) if (off < 0 || off >= 1) fail("offsets must lie in [0,1)");
    for (Real al : o.alphas) if (al < 0 || al > 1) fail("alpha must lie in [0,1]");
    if (!o.maxNumberSet) o.limitOptions.maxNumber = defaultLimitOptions(o.model).maxNumber;
    if (o.model == Model::diffusion) o.schemes = {StressUpdate::USL};   // not used
    return o;
}

std::vector<AnalysisSetup> combinations(const Options& o)
{
    std::vector<AnalysisSetup> out;
    for (ShapeKind k : o.shapes)
        for (Real al : o.alphas)
            for (MassMatrix m : o.masses)
                for (StressUpdate sc : o.schemes)
                {
                    AnalysisSetup s;
                    s.model = o.model; s.shape = k; s.alpha = al; s.mass = m; s.scheme = sc;
                    s.offsets = o.offsets;
                    out.push_back(s);
                }
    return out;
}

std::string offsetsField(const std::vector<Real>& offs)
{
    std::ostringstream os;
    for (std::size_t i = 0; i < offs.size(); ++i) os << (i ? ";" : "") << offs[i];
    return os.str();
}

std::string setupFields(const AnalysisSetup& s)
{
    std::ostringstream os;
    os << modelName(s.model) << ',' << shapeShortName(s.shape) << ',' << s.alpha << ','
       << massMatrixName(s.mass) << ',' << (s.model == Model::wave ? stressUpdateName(s.scheme) : "-")
       << ',' << offsetsField(s.offsets);
    return os.str();
}

Real wrapAngle(Real x) { return std::remainder(x, 2*pi); }

void runModes(const Options& o, const std::vector<AnalysisSetup>& setups)
{
    if (o.numbers.empty()) return;
    const char* pname = o.model == Model::diffusion ? "Fo" : "CFL";
    std::ofstream csv;
    if (!o.csv.empty())
    {
        csv.open(o.csv);
        if (!csv) fail("cannot write " + o.csv);
        csv << "model,shape,alpha,mass,scheme,offsets,number,kh,theta,branch,Gre,Gim,absG,"
               "exactRe,exactIm,absExact,ampError,phaseError,match,spectralRadius,singular\n";
        csv.precision(16);
    }
    for (const AnalysisSetup& s : setups)
    {
        const int npc = s.pointsPerCell();
        std::printf("\n== %s\n", describe(s).c_str());
        std::printf("%6s %8s %3s %12s %12s %10s %10s %11s %7s %8s\n", pname, "kh/pi", "br",
                    "Re G", "Im G", "|G|", "|Gexact|", "phaseErr", "match", "rho(A)");
        // kh: the --kh list (every value printed), or khPerZone samples
        // per grid zone (the table prints multiples of pi/4)
        std::vector<std::pair<Real, bool>> khs;
        if (!o.khList.empty()) for (Real kh : o.khList) khs.emplace_back(kh, true);
        else for (int i = 1; i <= o.khPerZone*npc; ++i) khs.emplace_back(pi*i/o.khPerZone, (4*i) % o.khPerZone == 0);
        for (Real num : o.numbers)
            for (const auto& [kh, print] : khs)
            {
                for (const ModeResult& r : analyseMode(s, kh, num))
                {
                    const Real phaseErr = wrapAngle(std::arg(r.G) - std::arg(r.exact));
                    if (csv)
                        csv << setupFields(s) << ',' << num << ',' << kh << ',' << r.theta << ','
                            << r.branch << ',' << r.G.real() << ',' << r.G.imag() << ','
                            << std::abs(r.G) << ',' << r.exact.real() << ',' << r.exact.imag() << ','
                            << std::abs(r.exact) << ',' << std::abs(r.G) - std::abs(r.exact) << ','
                            << phaseErr << ',' << r.match << ',' << r.spectralRadius << ','
                            << int(r.singular) << '\n';
                    if (print)
                        std::printf("%6.3f %8.3f %3d %12.6f %12.6f %10.6f %10.6f %11.3e %7.4f %8.5f\n",
                                    num, kh/pi, r.branch, r.G.real(), r.G.imag(), std::abs(r.G),
                                    std::abs(r.exact), phaseErr, r.match, r.spectralRadius);
                }
            }
    }
    if (csv) std::printf("\nwrote %s\n", o.csv.c_str());
}

void runLimits(const Options& o, const std::vector<AnalysisSetup>& setups)
{
    if (!o.limit) return;
    const char* pname = o.model == Model::diffusion ? "Fo_max" : "CFL_max";
    std::ofstream csv;
    if (!o.limitCsv.empty())
    {
        csv.open(o.limitCsv);
        if (!csv) fail("cannot write " + o.limitCsv);
        csv << "model,shape,alpha,mass,scheme,offsets,limit,reachedMax\n";
        csv.precision(16);
    }
    std::printf("\nStability limits (largest %s with |G| <= 1+%g for all kh, searched in (0,%g])\n",
                o.model == Model::diffusion ? "Fo" : "CFL", o.limitOptions.slack,
                o.limitOptions.maxNumber);
    std::printf("%-5s %6s %-10s %-5s %-14s %12s\n", "shape", "alpha", "mass", "order", "offsets", pname);
    for (const AnalysisSetup& s : setups)
    {
        const StabilityLimit L = stabilityLimit(s, o.limitOptions);
        std::printf("%-5s %6.3f %-10s %-5s %-14s %s%11.6f\n", shapeShortName(s.shape), s.alpha,
                    massMatrixName(s.mass), s.model == Model::wave ? stressUpdateName(s.scheme) : "-",
                    offsetsField(s.offsets).c_str(), L.reachedMax ? ">=" : "  ", L.limit);
        if (csv) csv << setupFields(s) << ',' << L.limit << ',' << int(L.reachedMax) << '\n';
    }
    if (csv) std::printf("wrote %s\n", o.limitCsv.c_str());
}

void runSweep(const Options& o, const std::vector<AnalysisSetup>& setups)
{
    if (o.sweepPoints <= 0) return;
    std::vector<Real> shifts;
    for (int i = 0; i < o.sweepPoints; ++i) shifts.push_back((i + 0.5)/o.sweepPoints);
    std::ofstream csv;
    if (!o.sweepCsv.empty())
    {
        csv.open(o.sweepCsv);
        if (!csv) fail("cannot write " + o.sweepCsv);
        csv << "model,shape,alpha,mass,scheme,pattern,shift,limit,reachedMax\n";
        csv.precision(16);
    }
    std::printf("\nStability limit vs shift of the offset pattern\n");
    for (const AnalysisSetup& s : setups)
    {
        std::printf("== %s\n", describe(s).c_str());
        for (const auto& [shift, L] : limitVersusShift(s, shifts, o.limitOptions))
        {
            std::printf("  shift %6.4f  limit %s%.6f\n", shift, L.reachedMax ? ">=" : "", L.limit);
            if (csv) csv << setupFields(s) << ',' << shift << ',' << L.limit << ','
                         << int(L.reachedMax) << '\n';
        }
    }
    if (csv) std::printf("wrote %s\n", o.sweepCsv.c_str());
}

} // namespace

int main(int argc, char** argv)
{
    for (int i = 1; i + 1 < argc; ++i)
        if (std::string(argv[i]) == "--model" && std::string(argv[i + 1]) == "coupled") return runCoupled(argc, argv);
    const Options o = parse(argc, argv);
    const std::vector<AnalysisSetup> setups = combinations(o);
    if (o.numbers.empty() && !o.limit && o.sweepPoints <= 0)
    {
        usage();
        std::cerr << "\nnothing to do: give --Fo/--CFL values, --limit or --sweep-offsets\n";
        return 1;
    }
    runModes(o, setups);
    runLimits(o, setups);
    runSweep(o, setups);
    return 0;
}
