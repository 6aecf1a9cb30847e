#include "obstacles.H"
#include "choice.H"
#include "knownKeywords.H"
#include "surfaceWallShape.H"
#include "wallConditions.H"
#include <memory>

namespace
{

using namespace Foam;

std::array<mpm::Real, 3> arr(const vector& v) { return {v.x(), v.y(), v.z()}; }

// An STL obstacle must be closed (every edge between two triangles) with
// outward normals (positive enclosed volume): otherwise inside and outside
// are undefined, and points could be pushed into it.
void checkClosed(const triSurface& s, const dictionary& d, const word& name, const fileName& file)
{
    label open = 0;
    for (const labelList& ef : s.edgeFaces()) open += ef.size() != 2;
    if (open)
    {
        FatalIOErrorInFunction(d)
            << "Obstacle " << name << ": the STL " << file.c_str() << " is not closed ("
            << open << " edges do not join exactly two triangles)." << nl
            << "A level-set wall needs a closed surface: close it (e.g."
            << " surfaceCheck to find the holes) or use a plane obstacle."
            << exit(FatalIOError);
    }
    scalar volume = 0;
    const pointField& p = s.points();
    for (const labelledTri& f : s)
    {
        volume += (p[f[0]] & (p[f[1]] ^ p[f[2]]))/6;
    }
    if (volume <= 0)
    {
        FatalIOErrorInFunction(d)
            << "Obstacle " << name << ": the STL " << file.c_str() << " has inward "
            << "normals (enclosed volume " << volume << ")." << nl
            << "Orient them outwards, e.g. surfaceOrient " << file.name()
            << " '(x y z)' out.stl with a point outside it."
            << exit(FatalIOError);
    }
}

wordList shapeKeywords(const word& shape)
{
    if (shape == "plane") return {"point", "normal"};
    if (shape == "sphere") return {"centre", "radius"};
    if (shape == "cylinder") return {"point1", "point2", "radius"};
    if (shape == "box") return {"min", "max"};
    return {"file", "scale"};
}

} // namespace


std::vector<mpm::LevelSetWall> Foam::readObstacles
(
    const fvMesh& mesh,
    const dictionary& mpmDict,
    bool log,
    PtrList<Function1<vector>>* velocities
)
{
    std::vector<mpm::LevelSetWall> walls;
    const dictionary& obstacles = optionalSubDict(mpmDict, "obstacles");
    checkAllSubDicts(obstacles, "obstacles (one sub-dictionary per obstacle)");
    if (log && obstacles.size()) Info<< "Obstacles (level-set walls):" << nl;
    const wordList shapes{"plane", "sphere", "cylinder", "box", "stl"};
    for (const entry& e : obstacles)
    {
        if (!e.isDict()) continue;
        const dictionary& d = e.dict();
        const word name(e.keyword());
        if (!d.found("shape"))
        {
            FatalIOErrorInFunction(d)
                << "Obstacle " << name << " has no shape" << nl
                << "Valid shapes: " << spaceSeparated(shapes).c_str()
                << exit(FatalIOError);
        }
        const word shape(d.get<word>("shape"));
        if (!shapes.found(shape))
        {
            const word close(closestWord(shape, shapes));
            FatalIOErrorInFunction(d)
                << "Obstacle " << name << ": unknown shape '" << shape << "'"
                << (close.empty() ? "" : "; did you mean '" + close + "'?").c_str() << nl
                << "Valid shapes: " << spaceSeparated(shapes).c_str()
                << exit(FatalIOError);
        }
        wordList known{"shape", "type", "frictionCoefficient", "velocity", "velocityCoeffs"};
        known.append(shapeKeywords(shape));
        checkKeywords(d, known, "obstacle " + std::string(name));
        if (log) Info<< "    " << name << nl;

        mpm::LevelSetWall w;
        w.name = name;
        w.condition = readWallCondition(d, "obstacle " + std::string(name), "noSlip slip friction", log);

        try
        {
            if (shape == "plane")
            {
                w.shape = std::make_shared<mpm::HalfSpaceShape>
                (
                    arr(d.get<vector>("point")), arr(d.get<vector>("normal"))
                );
            }
            else if (shape == "sphere")
            {
                w.shape = std::make_shared<mpm::SphereShape>
                (
                    arr(d.get<vector>("centre")), d.get<scalar>("radius")
                );
            }
            else if (shape == "cylinder")
            {
                w.shape = std::make_shared<mpm::CylinderShape>
                (
                    arr(d.get<vector>("point1")), arr(d.get<vector>("point2")),
                    d.get<scalar>("radius")
                );
            }
            else if (shape == "box")
            {
                w.shape = std::make_shared<mpm::BoxShape>
                (
                    arr(d.get<vector>("min")), arr(d.get<vector>("max"))
                );
            }
            else
            {
                const fileName file
                (
                    mesh.time().constant()/"triSurface"/d.get<fileName>("file")
                );
                if (!isFile(file))
                {
                    FatalIOErrorInFunction(d)
                        << "Obstacle " << name << ": STL file " << file.c_str()
                        << " not found" << exit(FatalIOError);
                }
                const scalar scale = d.getOrDefault<scalar>("scale", 1);
                // Distance and sign from the same closed STL; the material
                // outside it
                const triSurface surf(file, scale);
                checkClosed(surf, d, name, file);
                w.shape = std::make_shared<surfaceWallShape>
                (
                    surf, std::make_shared<closedSurface>(surf), false,
                    "STL " + file.name() + ", " + std::to_string(surf.size()) + " triangles"
                );
            }
        }
        catch (const std::invalid_argument& err)
        {
            FatalIOErrorInFunction(d)
                << "Obstacle " << name << ": " << err.what() << exit(FatalIOError);
        }
        if (log) Info<< "        " << w.shape->describe().c_str() << nl;
        if (velocities)
        {
            velocities->setSize(label(walls.size()) + 1);
            if (d.found("velocity"))
            {
                velocities->set(label(walls.size()), Function1<vector>::New("velocity", d));
                if (log)
                {
                    Info<< "        moves with velocity "
                        << (*velocities)[label(walls.size())].type() << " (a Function1 of time)" << nl;
                }
            }
        }
        walls.push_back(std::move(w));
    }
    return walls;
}
