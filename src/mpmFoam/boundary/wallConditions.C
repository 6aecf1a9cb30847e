#include "wallConditions.H"
#include "choice.H"
#include "knownKeywords.H"
#include "DynamicList.H"
#include "cyclicPolyPatch.H"
#include "emptyPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "processorPolyPatch.H"

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
    wordList& conditionPatch
)
{
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
            if (side < 0)
            {
                FatalErrorInFunction
                    << "Face " << facei << " of patch " << pp.name() << " at "
                    << fc << " is not on the boundary of the box: MPM walls "
                    << "must be the sides of the domain" << exit(FatalError);
            }
            label ijk[3];
            ml.indicesOf(fc, ijk);
            const int a = side/2, a1 = (a + 1) % 3, a2 = (a + 2) % 3;
            const int lo = min(a1, a2), hi = max(a1, a2);
            spec.faceCondition[side][size_t(ijk[lo]) + size_t(L.nCells[lo])*ijk[hi]] = condition;
        }
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
