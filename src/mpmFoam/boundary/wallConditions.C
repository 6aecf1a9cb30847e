#include "wallConditions.H"
#include "choice.H"
#include "knownKeywords.H"
#include "DynamicList.H"
#include "cyclicPolyPatch.H"
#include "emptyPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "processorPolyPatch.H"
#include "surfaceWallShape.H"

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
    // Decomposed: any rank's faces count (their surfaces are gathered)
    labelList count(offBox.size());
    forAll(offBox, patchi) count[patchi] = offBox[patchi].size();
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
    forAll(offBox, patchi)
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

} // namespace


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
    const scalar tol = 1e-6*L.h;
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
                wc.type = readChoice
                (
                    d, "type", mpm::parseWallType,
                    [](mpm::WallType t) { return mpm::wallTypeName(t); },
                    mpm::validWallTypeNames(), mpm::WallType::noSlip
                );
                if (wc.type == mpm::WallType::periodic)
                {
                    FatalIOErrorInFunction(d)
                        << "Patch " << pp.name() << " is not cyclic: a periodic "
                        << "wall needs a cyclic patch pair in blockMeshDict"
                        << exit(FatalIOError);
                }
                if (wc.type == mpm::WallType::friction)
                {
                    if (!d.found("frictionCoefficient"))
                    {
                        FatalIOErrorInFunction(d)
                            << "Missing keyword frictionCoefficient for the "
                            << "friction wall " << pp.name()
                            << " (Coulomb coefficient, >= 0)"
                            << exit(FatalIOError);
                    }
                    wc.frictionCoefficient =
                        readBounded(d, "frictionCoefficient", 0, 0, GREAT);
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
            int side = -1;
            for (int a = 0; a < 3 && side < 0; ++a)
            {
                if (!L.solved[a]) continue;
                if (mag(fc[a] - L.origin[a]) < tol) side = 2*a;
                else if (mag(fc[a] - L.origin[a] - L.length(a)) < tol) side = 2*a + 1;
            }
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
                if (t == mpm::WallType::inlet || t == mpm::WallType::periodic)
                {
                    FatalErrorInFunction
                        << "Patch " << pp.name() << " is " << mpm::wallTypeName(t)
                        << " but its face " << facei << " at " << fc << " is "
                        << "not on a side of the MPM lattice's box "
                        << "(origin " << point(L.origin[0], L.origin[1], L.origin[2])
                        << ", h " << L.h << "): inlets and periodic patches"
                        << " must lie on its sides for now (outlets and walls"
                        << " may lie anywhere)" << exit(FatalError);
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
        // Lattice faces no patch covers lie beyond the mesh (its box
        // reaches past the bounding box): nothing reaches them
        label uncovered = 0;
        for (auto& fcs : spec.faceCondition) for (const int c : fcs) uncovered += c < 0;
        if (uncovered)
        {
            const label outside = label(spec.conditions.size());
            spec.conditions.push_back(mpm::WallCondition{});
            names.append("beyondMesh");
            for (auto& fcs : spec.faceCondition) for (int& c : fcs) if (c < 0) c = outside;
        }
        readPatchWalls(mesh, spec, patchCondition, offBox, patchWalls);
    }

    for (int side = 0; side < 6; ++side)
    {
        if (Pstream::parRun())
        {
            // Each rank knows its own boundary faces: combine.
            List<int> fc(spec.faceCondition[side].begin(), spec.faceCondition[side].end());
            Pstream::listCombineGather(fc, maxEqOp<int>());
            Pstream::listCombineScatter(fc);
            std::copy(fc.begin(), fc.end(), spec.faceCondition[side].begin());
        }
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
