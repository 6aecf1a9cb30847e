#include "wallConditions.H"
#include "choice.H"
#include "cyclicPolyPatch.H"
#include "emptyPolyPatch.H"

mpm::BoundarySpec Foam::readWallConditions
(
    const fvMesh& mesh,
    const meshLattice& ml,
    const dictionary& mpmDict
)
{
    const mpm::Lattice& L = ml.lattice();
    const dictionary& walls = mpmDict.subOrEmptyDict("walls");
    mpm::BoundarySpec spec;
    spec.conditions.clear();

    for (int side = 0; side < 6; ++side)
    {
        const int a = side/2, a1 = (a + 1) % 3, a2 = (a + 2) % 3;
        const int lo = min(a1, a2), hi = max(a1, a2);
        spec.faceCondition[side].assign(size_t(L.nCells[lo])*L.nCells[hi], -1);
    }

    Info<< "Walls:" << nl;
    const scalar tol = 1e-6*L.h;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<emptyPolyPatch>(pp) || pp.empty()) continue;

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
            }
        }
        const int condition = int(spec.conditions.size());
        spec.conditions.push_back(wc);

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
    return spec;
}
