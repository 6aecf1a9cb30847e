#include "wallConditions.H"
#include "choice.H"
#include "knownKeywords.H"
#include "DynamicList.H"
#include "cyclicPolyPatch.H"
#include "emptyPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "processorPolyPatch.H"
#include "surfaceWallShape.H"
#include <sstream>

namespace
{

using namespace Foam;

// Every walls entry must be a dictionary of known keywords that names (or
// matches, as a regular expression) at least one patch; otherwise the patch
// meant would silently be noSlip. Matched against the patch names, not their
// faces: decomposed, a processor has every patch, some with no faces here.
// Processor patches differ between ranks and are never walls.
void checkWallEntries(const fvMesh& mesh, const dictionary& walls)
{
    checkAllSubDicts(walls, "walls (one sub-dictionary per patch)");
    DynamicList<word> patches;
    std::string patchNames;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<processorPolyPatch>(pp)) continue;
        patches.append(pp.name());
        patchNames += " " + pp.name();
    }
    for (const entry& e : walls)
    {
        const keyType& key = e.keyword();
        if (key[0] == '#' || key[0] == '$') continue;
        // Each type its own keywords: a flow rate on a wall, or a friction
        // coefficient on an inlet, would otherwise be silently ignored.
        const word type(e.dict().getOrDefault<word>("type", "noSlip"));
        const wordList wallKeys{"type", "frictionCoefficient"};
        checkKeywords
        (
            e.dict(),
            type == "inlet" ? inletKeywords()
          : type == "outlet" ? wordList{"type"} : wallKeys,
            (type == "inlet" || type == "outlet" ? type + " " : word("wall "))
          + std::string(key)
        );
        bool matched = false;
        for (const word& p : patches) matched = matched || key.match(p);
        if (matched) continue;
        const word close(key.isPattern() ? word::null : closestWord(key, patches));
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            walls.name(), e.startLineNumber(), e.endLineNumber()
        )   << "walls entry '" << key.c_str() << "' matches no patch of the "
            << "mesh" << (close.empty() ? "" : "; did you mean '" + close + "'?")
            .c_str() << nl
            << "Patches of the mesh:" << patchNames.c_str() << nl
            << "(unlisted patches are noSlip, cyclic ones periodic)"
            << exit(FatalIOError);
    }
}

// The wall patches' faces off the lattice box's sides as level-set walls,
// one per patch, with the patch's condition: the distance to the patch's
// faces, its sign from the mesh's whole boundary (empty patches included,
// so that a 2D mesh's boundary is closed), the material inside the mesh.
void readPatchWalls
(
    const fvMesh& mesh,
    const mpm::BoundarySpec& spec,
    const labelList& patchCondition,
    const List<DynamicList<label>>& offBox,
    std::vector<mpm::LevelSetWall>& walls
)
{
    // Decomposed: any rank's faces count (their surfaces are gathered).
    // The patches every rank has, in the same order: the processor patches
    // come after them, as many as the rank has neighbours (periodic
    // patches lie on the lattice's sides, so no processorCyclic face is
    // off it)
    labelList count(mesh.boundaryMesh().nNonProcessor());
    forAll(count, patchi) count[patchi] = offBox[patchi].size();
    Pstream::listCombineGather(count, plusEqOp<label>());
    Pstream::listCombineScatter(count);
    if (sum(count) == 0) return;
    const polyBoundaryMesh& bm = mesh.boundaryMesh();
    // The domain's whole boundary: every patch but those between processors
    // (a cyclic's processor part is the cyclic's)
    DynamicList<label> all;
    for (const polyPatch& pp : bm)
    {
        if (isA<processorPolyPatch>(pp) && !isA<processorCyclicPolyPatch>(pp)) continue;
        for (label i = 0; i < pp.size(); ++i) all.append(pp.start() + i);
    }
    const auto sign = std::make_shared<closedSurface>(triangulate(mesh, all));
    Info<< "Walls off the lattice box's sides (level sets, docs/geometry.md):" << nl;
    forAll(count, patchi)
    {
        if (count[patchi] == 0) continue;
        mpm::LevelSetWall w;
        w.name = bm[patchi].name();
        w.condition = spec.conditions[patchCondition[patchi]];
        w.specCondition = int(patchCondition[patchi]);
        w.shape = std::make_shared<surfaceWallShape>
        (
            triangulate(mesh, offBox[patchi]), sign, true,
            "patch " + w.name + ", " + std::to_string(count[patchi]) + " faces"
        );
        Info<< "    " << w.shape->describe().c_str() << ": "
            << mpm::wallTypeName(w.condition.type) << nl;
        walls.push_back(std::move(w));
    }
}

// Lattice faces no patch covers lie beyond the mesh (the lattice's box is
// its bounding box rounded up to whole cells). Material within a cell or two
// of a level-set wall near them reaches their ghost nodes through its
// stencils. Each takes the condition of the level-set wall nearest its
// centre: noSlip mirrors there as before; an outlet's own condition (free
// nodes, and its booking); a slip or friction wall's own mirror where the
// wall is parallel to the face (the image holds a bed beside it: free
// nodes let a bed beside slip walls creep 0.47 mm in 0.01 s,
// tests/cases/anyMesh.sh "pier bed"); free nodes beyond any other wall (an
// outlet condition "beyondMesh" whose points are held, as at a wall:
// WallCondition::holdsPoints; the level-set wall itself removes or holds
// what would reach the face). A noSlip mirror there held a stream entering
// through a level-set inlet in the last cell row, and a slip mirror on a box
// side turns a stream along a tilted slip wall
// (tests/cases/openBoundaryInletAnyMesh.sh: 6 mm at the rotated outlet's
// corner; free nodes: 3.7e-6 m).
void conditionsBeyondMesh
(
    const meshLattice& ml,
    const std::vector<mpm::LevelSetWall>& patchWalls,
    mpm::BoundarySpec& spec,
    DynamicList<word>& names
)
{
    const mpm::Lattice& L = ml.lattice();
    label beyondFree = -1, beyondNone = -1;
    label counts[3] = {0, 0, 0};   // own condition, free, no wall at all
    // The condition "beyondMesh" of the given type, added once
    auto beyond = [&](label& index, mpm::WallType type)
    {
        if (index < 0)
        {
            index = label(spec.conditions.size());
            mpm::WallCondition c;
            c.type = type;
            // Free nodes, but a point that reaches the face went through a
            // level-set wall or the corner where it meets a mirrored side:
            // held there, the level set puts it back (it left the domain at
            // the toe of granularSlideWave's slope on its mirrored floor)
            c.holdsPoints = true;
            spec.conditions.push_back(c);
            names.append("beyondMesh");
        }
        return int(index);
    };
    for (int side = 0; side < 6; ++side)
    {
        const int a = side/2, a1 = (a + 1) % 3, a2 = (a + 2) % 3;
        const int lo = min(a1, a2), hi = max(a1, a2);
        auto& fcs = spec.faceCondition[side];
        for (size_t f = 0; f < fcs.size(); ++f)
        {
            if (fcs[f] >= 0) continue;
            int r[3];
            r[lo] = int(f % size_t(L.nCells[lo]));
            r[hi] = int(f/size_t(L.nCells[lo]));
            r[a] = side % 2 == 0 ? 0 : L.nCells[a] - 1;
            point x(ml.cellCentre(label(L.cellIndex(r[0], r[1], r[2]))));
            if (L.solved[a]) x[a] = L.origin[a] + (side % 2 == 0 ? 0 : L.length(a));
            const mpm::Real xr[3] = {x.x(), x.y(), x.z()};
            mpm::Real n[3], nearestNormal[3] = {0, 0, 0};
            int nearest = -1;
            scalar best = GREAT;
            for (size_t w = 0; w < patchWalls.size(); ++w)
            {
                const scalar d = mag(patchWalls[w].shape->distance(xr, n, 8*L.h));
                if (d < best)
                {
                    best = d;
                    nearest = int(w);
                    for (int k = 0; k < 3; ++k) nearestNormal[k] = n[k];
                }
            }
            if (nearest < 0)
            {
                // No level-set wall at all: a noSlip mirror, as before
                fcs[f] = beyond(beyondNone, mpm::WallType::noSlip);
                ++counts[2];
                continue;
            }
            const mpm::LevelSetWall& w = patchWalls[size_t(nearest)];
            const mpm::WallType t = w.condition.type;
            // A slip or friction wall parallel to the face mirrors there as
            // on a box side (the image of the material's stress holds it)
            const bool parallel = mag(nearestNormal[a]) > 1 - 1e-6;
            if
            (
                t == mpm::WallType::noSlip || t == mpm::WallType::outlet
             || (parallel && (t == mpm::WallType::slip || t == mpm::WallType::friction))
            )
            {
                fcs[f] = w.specCondition;
                ++counts[0];
                continue;
            }
            fcs[f] = beyond(beyondFree, mpm::WallType::outlet);
            ++counts[1];
        }
    }
    if (counts[0] + counts[1] + counts[2])
    {
        Info<< "    lattice faces beyond the mesh: " << counts[0] << " take the"
            << " condition of the nearest patch, " << counts[1] << " are"
            << " free (outlet beyondMesh), " << counts[2] << " noSlip" << nl;
    }
}

} // namespace


mpm::WallCondition Foam::readWallCondition
(
    const dictionary& d, const std::string& what, const char* valid, bool echo
)
{
    mpm::WallCondition wc;
    wc.type = readChoice
    (
        d, "type",
        [&](const std::string& s, mpm::WallType& t)
        {
            std::istringstream names(valid);
            std::string v;
            while (names >> v) if (v == s) return mpm::parseWallType(s, t);
            return false;
        },
        [](mpm::WallType t) { return mpm::wallTypeName(t); },
        valid, mpm::WallType::noSlip, echo
    );
    if (wc.type == mpm::WallType::friction)
    {
        if (!d.found("frictionCoefficient"))
        {
            FatalIOErrorInFunction(d)
                << "Missing keyword frictionCoefficient for the friction "
                << what.c_str() << " (Coulomb coefficient, >= 0)"
                << exit(FatalIOError);
        }
        wc.frictionCoefficient = readBounded(d, "frictionCoefficient", 0, 0, GREAT, echo);
    }
    else if (d.found("frictionCoefficient"))
    {
        FatalIOErrorInFunction(d)
            << "The " << what.c_str() << " is " << mpm::wallTypeName(wc.type)
            << ": frictionCoefficient needs type friction"
            << exit(FatalIOError);
    }
    return wc;
}

int Foam::latticeBoxSide(const mpm::Lattice& L, const point& x)
{
    const scalar tol = 1e-6*L.h;
    for (int a = 0; a < 3; ++a)
    {
        if (!L.solved[a]) continue;
        if (mag(x[a] - L.origin[a]) < tol) return 2*a;
        if (mag(x[a] - L.origin[a] - L.length(a)) < tol) return 2*a + 1;
    }
    return -1;
}


const Foam::wordList& Foam::inletKeywords()
{
    static const wordList keys
    {
        "type", "velocity", "material", "pointsPerCell",
        "massFlowRate", "volumeFlowRate",
        "massFlowRateCoeffs", "volumeFlowRateCoeffs"
    };
    return keys;
}


mpm::BoundarySpec Foam::readWallConditions
(
    const fvMesh& mesh,
    const meshLattice& ml,
    const dictionary& mpmDict,
    wordList& conditionPatch,
    std::vector<mpm::LevelSetWall>& patchWalls
)
{
    patchWalls.clear();
    const mpm::Lattice& L = ml.lattice();
    const dictionary& walls = optionalSubDict(mpmDict, "walls");
    checkWallEntries(mesh, walls);
    mpm::BoundarySpec spec;
    spec.conditions.clear();
    DynamicList<word> names;

    for (int side = 0; side < 6; ++side)
    {
        const int a = side/2, a1 = (a + 1) % 3, a2 = (a + 2) % 3;
        const int lo = min(a1, a2), hi = max(a1, a2);
        spec.faceCondition[side].assign(size_t(L.nCells[lo])*L.nCells[hi], -1);
    }

    Info<< "Walls:" << nl;
    // Condition index of each patch, faces or not. Decomposed, every rank
    // has the same patches (some empty here) before its processor patches,
    // so the indices agree and the ranks' faces can be combined below.
    labelList patchCondition(mesh.boundaryMesh().size(), -1);
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(pp) || isA<processorPolyPatch>(pp)) continue;

        mpm::WallCondition wc;
        if (isA<cyclicPolyPatch>(pp))
        {
            wc.type = mpm::WallType::periodic;
            Info<< "    " << pp.name() << " periodic (cyclic patch)" << nl;
        }
        else
        {
            const entry* e = walls.findEntry(pp.name(), keyType::REGEX);
            if (!e || !e->isDict())
            {
                Info<< "    " << pp.name() << " noSlip (default)" << nl;
            }
            else
            {
                const dictionary& d = e->dict();
                Info<< "    " << pp.name() << nl;
                wc = readWallCondition(d, "wall " + pp.name(), mpm::validWallTypeNames());
                if (wc.type == mpm::WallType::periodic)
                {
                    FatalIOErrorInFunction(d)
                        << "Patch " << pp.name() << " is not cyclic: a periodic "
                        << "wall needs a cyclic patch pair in blockMeshDict"
                        << exit(FatalIOError);
                }
                if (wc.type == mpm::WallType::inlet)
                {
                    // The velocity of the entering material, imposed on the
                    // lattice beyond the face (its direction is checked
                    // against the face by openBoundaries)
                    if (!d.found("velocity"))
                    {
                        FatalIOErrorInFunction(d)
                            << "Missing keyword velocity for the inlet "
                            << pp.name() << " (the entering material's "
                            << "velocity, a vector pointing into the domain)"
                            << exit(FatalIOError);
                    }
                    const vector U(d.get<vector>("velocity"));
                    Info<< "        velocity " << U << nl;
                    for (direction c = 0; c < 3; ++c) wc.velocity[c] = U[c];
                }
            }
        }
        patchCondition[pp.index()] = label(spec.conditions.size());
        spec.conditions.push_back(wc);
        names.append(pp.name());
    }

    // Faces of each patch that are not on the lattice box's sides: level-set
    // walls (a mesh that is not a uniform box)
    List<DynamicList<label>> offBox(mesh.boundaryMesh().size());
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        // A cyclic split by the decomposition is a processorCyclic patch:
        // its faces are its cyclic's (periodic) faces.
        label condition = patchCondition[pp.index()];
        if (isA<processorCyclicPolyPatch>(pp))
        {
            condition = patchCondition[refCast<const processorCyclicPolyPatch>(pp).referPatchID()];
        }
        if (condition < 0) continue;
        forAll(pp, facei)
        {
            const point& fc = pp.faceCentres()[facei];
            const int side = latticeBoxSide(L, fc);
            if (side < 0 && ml.cellsAreNodes())
            {
                FatalErrorInFunction
                    << "Face " << facei << " of patch " << pp.name() << " at "
                    << fc << " is not on the boundary of the box: MPM walls "
                    << "must be the sides of the domain" << exit(FatalError);
            }
            if (side < 0)
            {
                const mpm::WallType t = spec.conditions[condition].type;
                if (t == mpm::WallType::periodic)
                {
                    // A cyclic on the mesh's bounding box misses the
                    // lattice's side when the spacing does not divide the
                    // period: name spacings that do
                    const boundBox bb(mesh.points(), true);
                    const vector nf(pp.faceNormals()[facei]);
                    direction a = 0;
                    for (direction i = 1; i < 3; ++i) if (mag(nf[i]) > mag(nf[a])) a = i;
                    const scalar len = bb.span()[a];
                    const label n0 = max(label(1), label(std::floor(len/L.h))), n1 = n0 + 1;
                    FatalErrorInFunction
                        << "Patch " << pp.name() << " is " << mpm::wallTypeName(t)
                        << " but its face " << facei << " at " << fc << " is "
                        << "not on a side of the MPM lattice's box "
                        << "(origin " << point(L.origin[0], L.origin[1], L.origin[2])
                        << ", h " << L.h << "): periodic patches must lie on"
                        << " its sides (walls, outlets and inlets may lie"
                        << " anywhere)." << nl << "The mesh is " << len
                        << " long in direction " << label(a) << ": give a lattice"
                        << " spacing that divides it, e.g. lattice { spacing "
                        << len/n1 << "; } (" << n1 << " cells) or " << len/n0
                        << " (" << n0 << " cells)" << exit(FatalError);
                }
                offBox[pp.index()].append(pp.start() + facei);
                continue;
            }
            const int a = side/2, a1 = (a + 1) % 3, a2 = (a + 2) % 3;
            const int lo = min(a1, a2), hi = max(a1, a2);
            auto& fcs = spec.faceCondition[side];
            if (ml.cellsAreNodes())
            {
                label ijk[3];
                ml.indicesOf(fc, ijk);
                fcs[size_t(ijk[lo]) + size_t(L.nCells[lo])*ijk[hi]] = condition;
                continue;
            }
            // The lattice's faces whose centres this face covers (a face
            // of a graded mesh may span several, or a part of one)
            const boundBox fb(pp.localPoints(), pp.localFaces()[facei], false);
            auto range = [&](int ax, label& i0, label& i1)
            {
                if (!L.solved[ax]) { i0 = 0; i1 = 0; return; }
                const scalar s0 = (fb.min()[ax] - L.origin[ax])/L.h - 0.5;
                const scalar s1 = (fb.max()[ax] - L.origin[ax])/L.h - 0.5;
                i0 = max(label(0), label(std::ceil(s0 - 1e-9)));
                i1 = min(label(L.nCells[ax] - 1), label(std::floor(s1 + 1e-9)));
            };
            label l0, l1, h0, h1;
            range(lo, l0, l1);
            range(hi, h0, h1);
            for (label j = h0; j <= h1; ++j)
            for (label i = l0; i <= l1; ++i)
            {
                fcs[size_t(i) + size_t(L.nCells[lo])*j] = condition;
            }
        }
    }
    if (!ml.cellsAreNodes())
    {
        readPatchWalls(mesh, spec, patchCondition, offBox, patchWalls);
    }
    if (Pstream::parRun())
    {
        // Each rank knows its own boundary faces: combine.
        for (int side = 0; side < 6; ++side)
        {
            List<int> fc(spec.faceCondition[side].begin(), spec.faceCondition[side].end());
            Pstream::listCombineGather(fc, maxEqOp<int>());
            Pstream::listCombineScatter(fc);
            std::copy(fc.begin(), fc.end(), spec.faceCondition[side].begin());
        }
    }
    if (!ml.cellsAreNodes())
    {
        // A lattice extent's sides inside the mesh: its wall condition
        label extentCondition = -1;
        for (int side = 0; side < 6; ++side)
        {
            if (!ml.extentSide(side)) continue;
            for (int& c : spec.faceCondition[side])
            {
                if (c >= 0) continue;
                if (extentCondition < 0)
                {
                    extentCondition = label(spec.conditions.size());
                    spec.conditions.push_back(ml.extentWall());
                    names.append("latticeExtent");
                }
                c = int(extentCondition);
            }
        }
        conditionsBeyondMesh(ml, patchWalls, spec, names);
    }
    for (int side = 0; side < 6; ++side)
    {
        if (!L.solved[side/2]) { spec.faceCondition[side].clear(); continue; }
        for (int& c : spec.faceCondition[side])
        {
            if (c < 0)
            {
                FatalErrorInFunction
                    << "A boundary face on side " << side << " of the box "
                    << "belongs to no patch" << exit(FatalError);
            }
        }
    }
    conditionPatch = names;
    return spec;
}
