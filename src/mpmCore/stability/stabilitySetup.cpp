#include "stabilitySetup.hpp"
#include <sstream>

namespace mpm {
namespace stability {

const char* modelName(Model m) { return m == Model::wave ? "wave" : "diffusion"; }
const char* massName(MassKind m) { return m == MassKind::consistent ? "consistent" : "lumped"; }

const char* schemeName(StressUpdate s)
{
    switch (s)
    {
        case StressUpdate::USF: return "USF";
        case StressUpdate::MUSL: return "MUSL";
        default: return "USL";
    }
}

bool parseModel(const std::string& n, Model& m)
{
    if (n == "diffusion") { m = Model::diffusion; return true; }
    if (n == "wave") { m = Model::wave; return true; }
    return false;
}

bool parseMass(const std::string& n, MassKind& m)
{
    if (n == "lumped") { m = MassKind::lumped; return true; }
    if (n == "consistent") { m = MassKind::consistent; return true; }
    return false;
}

bool parseScheme(const std::string& n, StressUpdate& s)
{
    if (n == "USL") { s = StressUpdate::USL; return true; }
    if (n == "USF") { s = StressUpdate::USF; return true; }
    if (n == "MUSL") { s = StressUpdate::MUSL; return true; }
    return false;
}

const char* shapeShortName(ShapeKind k)
{
    switch (k)
    {
        case ShapeKind::linearHat: return "LH";
        case ShapeKind::quadraticBSpline: return "QBS";
        default: return "CBS";
    }
}

std::string describe(const AnalysisSetup& s)
{
    std::ostringstream os;
    os << modelName(s.model) << ' ' << shapeShortName(s.shape)
       << " alpha=" << s.alpha << ' ' << massName(s.mass);
    if (s.model == Model::wave) os << ' ' << schemeName(s.scheme);
    os << " offsets=";
    for (std::size_t i = 0; i < s.offsets.size(); ++i) os << (i ? "," : "") << s.offsets[i];
    return os.str();
}

} // namespace stability
} // namespace mpm
