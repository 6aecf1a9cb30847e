#include "stabilitySetup.hpp"
#include "../common/enumTable.hpp"
#include <sstream>

namespace mpm {
namespace stability {

namespace
{
const auto models = enumTable<Model>({{Model::diffusion, "diffusion"}, {Model::wave, "wave"}});
}

const char* modelName(Model m) { return models.name(m); }
bool parseModel(const std::string& n, Model& m) { return models.parse(n, m); }

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
       << " alpha=" << s.alpha << ' ' << massMatrixName(s.mass);
    if (s.model == Model::wave) os << ' ' << stressUpdateName(s.scheme);
    os << " offsets=";
    for (std::size_t i = 0; i < s.offsets.size(); ++i) os << (i ? "," : "") << s.offsets[i];
    return os.str();
}

} // namespace stability
} // namespace mpm
