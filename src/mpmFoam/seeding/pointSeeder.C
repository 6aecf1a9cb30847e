#include "pointSeeder.H"
#include "meshCellSearch.H"
#include "searchableSurface.H"
#include "volumeType.H"
#include "Time.H"
#include "symmTensor.H"
#include "choice.H"
#include "knownKeywords.H"
#include "Tuple2.H"
#include <algorithm>

namespace
{

using namespace Foam;

word geometryType(const word& t)
{
    if (t == "box") return "searchableBox";
    if (t == "cylinder") return "searchableCylinder";
    if (t == "sphere") return "searchableSphere";
    if (t == "stl") return "triSurfaceMesh";
    return t;
}

// Checks a region's keywords: its own and its geometry's coefficients, which
// the searchableSurface reads (OpenFOAM v1912: sphere also takes origin).
// The geometry of a searchableSurface type not listed here is not known to
// us, so such a region is not checked.
void checkRegionKeywords(const dictionary& d, const word& name, const word& geometry)
{
    wordList keys
    {
        "type", "material", "pointsPerCell", "offset", "velocity", "stress",
        "solidFraction", "file", "overlap"
    };
    if (geometry == "searchableBox") keys.append(wordList{"min", "max"});
    else if (geometry == "searchableCylinder") keys.append(wordList{"point1", "point2", "radius"});
    else if (geometry == "searchableSphere") keys.append(wordList{"centre", "origin", "radius"});
    else if (geometry == "triSurfaceMesh") keys.append(wordList{"scale", "minQuality"});
    else return;
    checkKeywords(d, keys, "region " + name + " (type " + d.get<word>("type") + ")");
}

// Lattice cells (global linear index, lattice order) whose sub-cell points
// can fall in this rank's cells: its own and, decomposed, one layer more.
std::vector<label> sourceCells(const meshLattice& ml)
{
    const mpm::Lattice& L = ml.lattice();
    const int layer = Pstream::parRun() ? 1 : 0;
    std::vector<label> cells;
    for (const auto& r : ml.ownedLatticeCells())
    {
        for (int dk = -layer; dk <= layer; ++dk)
        for (int dj = -layer; dj <= layer; ++dj)
        for (int di = -layer; di <= layer; ++di)
        {
            const int d[3] = {di, dj, dk};
            int c[3];
            bool ok = true;
            for (int a = 0; a < 3; ++a)
            {
                c[a] = r[a] + d[a];
                ok = ok && c[a] >= 0 && c[a] < L.nCells[a];
            }
            if (ok) cells.push_back(label(L.cellIndex(c[0], c[1], c[2])));
        }
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return cells;
}

// Initial velocity at x for a region's velocity dictionary.
class velocityField
{
    word type_;
    vector value_, amplitude_, wavenumber_;
    scalar phase_ = 0;

public:
    explicit velocityField(const dictionary& d)
    :
        type_(d.getOrDefault<word>("type", "uniform")),
        value_(Zero), amplitude_(Zero), wavenumber_(Zero)
    {
        if (type_ == "uniform")
        {
            checkKeywords(d, {"type", "value"}, "velocity (type uniform)");
            value_ = d.getOrDefault<vector>("value", Zero);
        }
        else if (type_ == "sine")
        {
            checkKeywords
            (
                d, {"type", "amplitude", "wavenumber", "phase"},
                "velocity (type sine)"
            );
            amplitude_ = d.get<vector>("amplitude");
            wavenumber_ = d.get<vector>("wavenumber");
            phase_ = d.getOrDefault<scalar>("phase", 0);
        }
        else
        {
            FatalIOErrorInFunction(d)
                << "Unknown velocity type '" << type_ << "'" << nl
                << "Valid velocity types: uniform sine" << exit(FatalIOError);
        }
    }

    vector operator()(const point& x) const
    {
        return type_ == "uniform"
            ? value_
            : amplitude_*std::sin((wavenumber_ & x) + phase_);
    }
};

// Overlapping regions: the later region wins. Removes the points of earlier
// regions (indices from `first` on) that lie inside `surf`, keeping the
// order of the others (and of regionOf, each point's region). Returns the
// global count and mass removed.
Tuple2<label, scalar> removeInside
(
    const searchableSurface& surf,
    mpm::Particles& points,
    const label first,
    std::vector<label>& regionOf
)
{
    const label n = points.size();
    pointField x(n - first);
    forAll(x, i)
    {
        const label p = first + i;
        x[i] = point(points.x[0][p], points.x[1][p], points.x[2][p]);
    }
    List<volumeType> inside;
    surf.getVolumeType(x, inside);
    std::vector<mpm::Index> order, removed;
    for (label p = 0; p < n; ++p)
    {
        if (p >= first && inside[p - first] == volumeType::INSIDE) removed.push_back(p);
        else order.push_back(p);
    }
    scalar mass = 0;
    for (const mpm::Index p : removed) mass += points.mass[p];
    if (!removed.empty())
    {
        const label kept = label(order.size());
        order.insert(order.end(), removed.begin(), removed.end());
        points.permute(order);
        points.resize(kept);
        std::vector<label> r(kept);
        for (label i = 0; i < kept; ++i) r[i] = regionOf[order[i]];
        regionOf.swap(r);
    }
    return Tuple2<label, scalar>
    (
        returnReduce(label(removed.size()), sumOp<label>()),
        returnReduce(mass, sumOp<scalar>())
    );
}

// Count and mass of the points of each region and each material (global)
void reportTotals
(
    const mpm::Particles& points,
    const label first,
    const std::vector<label>& regionOf,
    const wordList& regionNames,
    const wordList& materialNames
)
{
    scalarField regionMass(regionNames.size(), 0), materialMass(materialNames.size(), 0);
    labelList regionCount(regionNames.size(), 0), materialCount(materialNames.size(), 0);
    for (label p = first; p < points.size(); ++p)
    {
        const label r = regionOf[p], m = points.material[p];
        regionMass[r] += points.mass[p]; ++regionCount[r];
        materialMass[m] += points.mass[p]; ++materialCount[m];
    }
    for (auto* f : {&regionMass, &materialMass})
    {
        Pstream::listCombineGather(*f, plusEqOp<scalar>());
        Pstream::listCombineScatter(*f);
    }
    for (auto* f : {&regionCount, &materialCount})
    {
        Pstream::listCombineGather(*f, plusEqOp<label>());
        Pstream::listCombineScatter(*f);
    }
    Info<< nl << "Seeded (after overlaps: a later region replaces the earlier"
        << " ones where they overlap):" << nl;
    forAll(regionNames, r)
    {
        Info<< "    region " << regionNames[r] << ": " << regionCount[r]
            << " points, mass " << regionMass[r] << nl;
    }
    forAll(materialNames, m)
    {
        if (materialCount[m] == 0) continue;
        Info<< "    material " << materialNames[m] << ": " << materialCount[m]
            << " points, mass " << materialMass[m] << nl;
    }
}

} // namespace

Foam::Vector<Foam::label> Foam::readPointsPerCell
(
    const dictionary& d,
    const mpm::Lattice& L
)
{
    Vector<label> ppc(1, 1, 1);
    const entry* pe = d.findEntry("pointsPerCell", keyType::LITERAL);
    if (!pe)
    {
        FatalIOErrorInFunction(d)
            << "Missing keyword pointsPerCell (a count per direction, "
            << "e.g. 2 or (2 2 1))" << exit(FatalIOError);
    }
    if (pe->stream()[0].isPunctuation()) ppc = d.get<Vector<label>>("pointsPerCell");
    else ppc = Vector<label>::uniform(d.get<label>("pointsPerCell"));
    for (direction a = 0; a < 3; ++a)
    {
        if (!L.solved[a]) ppc[a] = 1;
        if (ppc[a] < 1 || ppc[a] > 10)
        {
            FatalIOErrorInFunction(d)
                << "pointsPerCell " << ppc << " must be between 1 and 10"
                << exit(FatalIOError);
        }
    }
    return ppc;
}

Foam::label Foam::seedRegions
(
    const fvMesh& mesh,
    const meshLattice& ml,
    const materialLibrary& materials,
    const dictionary& regions,
    mpm::Particles& points
)
{
    const mpm::Lattice& L = ml.lattice();
    const label n0 = points.size();
    label idBase = returnReduce(n0, sumOp<label>());

    checkAllSubDicts(regions, "regions (one sub-dictionary per region)");
    std::vector<label> regionOf(n0, -1);    // each point's region
    wordList regionNames;
    for (const entry& e : regions)
    {
        if (!e.isDict()) continue;
        const dictionary& d = e.dict();
        const word name(e.keyword());
        const label regioni = regionNames.size();
        regionNames.append(name);
        Info<< "Region " << name << nl;

        dictionary geomDict(d);
        geomDict.set("type", geometryType(d.get<word>("type")));
        checkRegionKeywords(d, name, geomDict.get<word>("type"));
        autoPtr<searchableSurface> surf = searchableSurface::New
        (
            geomDict.get<word>("type"),
            IOobject(d.getOrDefault<word>("file", name), mesh.time().constant(),
                "triSurface", mesh.time(), IOobject::MUST_READ, IOobject::NO_WRITE),
            geomDict
        );

        // Points of a region reaching outside the mesh would be lost.
        const boundBox rb(surf->bounds());
        const scalar tol = 1e-9*L.h;
        for (direction a = 0; a < 3; ++a)
        {
            if (!L.solved[a]) continue;
            if (rb.min()[a] < L.origin[a] - tol || rb.max()[a] > L.origin[a] + L.length(a) + tol)
            {
                FatalIOErrorInFunction(d)
                    << "Region " << name << " " << rb << " reaches outside "
                    << "the mesh (direction " << label(a) << ", mesh from "
                    << L.origin[a] << " to " << L.origin[a] + L.length(a)
                    << "): points would be seeded outside the mesh." << nl
                    << "Shrink the region or enlarge the mesh (or the MPM"
                    << " lattice's extent, lattice { extent ...; })"
                    << exit(FatalIOError);
            }
        }

        // The later region wins: the points of earlier regions inside this
        // one go (seeding both would double the mass in the overlap), unless
        // it says `overlap add` (a mixture: each region its solidFraction).
        const bool add = readChoice
        (
            d, "overlap",
            [](const std::string& w, bool& v)
            {
                v = w == "add";
                return v || w == "replace";
            },
            [](bool v) { return v ? "add" : "replace"; },
            "replace add", false, false
        );
        const Tuple2<label, scalar> replaced
        (
            add ? Tuple2<label, scalar>(0, 0) : removeInside(surf(), points, n0, regionOf)
        );
        if (add) Info<< "    overlap add: earlier points kept" << nl;
        if (replaced.first())
        {
            Info<< "    replaces " << replaced.first() << " points (mass "
                << replaced.second() << ") of earlier regions where they "
                << "overlap" << nl;
        }

        const label mat = materials.index(d.get<word>("material"), d);
        const Vector<label> ppc(readPointsPerCell(d, L));
        // Shift of the sub-cell pattern, as a fraction of a cell: lets
        // analysis runs place points anywhere relative to the lattice nodes
        // (which sit at cell centres).
        const vector shift(d.getOrDefault<vector>("offset", Zero));
        for (direction a = 0; a < 3; ++a)
        {
            if (shift[a] <= -0.5 || shift[a] >= 0.5)
            {
                FatalIOErrorInFunction(d)
                    << "offset " << shift << " must lie in (-0.5, 0.5) in "
                    << "every direction (fraction of a cell)"
                    << exit(FatalIOError);
            }
        }
        for (direction a = 0; a < 3; ++a)
        {
            if (L.solved[a] && ppc[a] % 2 == 1 && mag(shift[a]) < 1e-12)
            {
                WarningInFunction
                    << "Region " << name << ": " << ppc[a] << " points per "
                    << "cell in direction " << label(a) << " puts points on "
                    << "the lattice nodes (cell centres), where they are "
                    << "fragile (docs/stabilityAnalysis.md). Prefer an even "
                    << "number or an offset." << endl;
                break;
            }
        }
        const velocityField velocity(optionalSubDict(d, "velocity"));
        const symmTensor sigma0(d.getOrDefault<symmTensor>("stress", Zero));
        // Share of the cell the grains fill: a suspension or a packed bed in
        // a fluid. A point is a parcel of mixture: its volume is its share of
        // the cell, its mass rho solidFraction volume (rho: grain density).
        const scalar solidFraction = readBounded(d, "solidFraction", 1, SMALL, 1, false);
        const scalar rho = materials.rho(mat);

        // Candidate points: a regular sub-lattice in every cell. Decomposed,
        // a rank keeps the points that fall in its cells (a shifted pattern
        // can reach a neighbour cell), and ids are numbered as in a serial
        // run: by region, source cell (lattice order) and sub-point.
        const label perCell = ppc.x()*ppc.y()*ppc.z();
        const scalar pointVol = ml.cellVolume()/perCell;
        const std::vector<label> sources(sourceCells(ml));
        pointField candidates(sources.size()*perCell);
        label c = 0;
        for (const label src : sources)
        {
            const point cc(ml.cellCentre(src));
            for (label k = 0; k < ppc.z(); ++k)
            for (label j = 0; j < ppc.y(); ++j)
            for (label i = 0; i < ppc.x(); ++i)
            {
                const label idx[3] = {i, j, k};
                point x(cc);
                for (direction a = 0; a < 3; ++a)
                {
                    if (L.solved[a]) x[a] += ((idx[a] + 0.5)/ppc[a] - 0.5 + shift[a])*L.h;
                }
                candidates[c++] = x;
            }
        }
        List<volumeType> inside;
        surf->getVolumeType(candidates, inside);
        if (!ml.cellsAreNodes())
        {
            // The lattice is its own: its cells reach beyond the mesh.
            // Decomposed, a point of this rank's lattice cells may lie in
            // another rank's mesh cells: the mesh is asked as a whole
            // (meshCellSearch.H), for the points this rank keeps; each is
            // counted by the rank owning its lattice cell, as serially.
            DynamicList<label> mine;
            forAll(candidates, i)
            {
                if (inside[i] != volumeType::INSIDE) continue;
                label ijk[3];
                ml.indicesOf(candidates[i], ijk);
                if (ml.ownsLatticeCell(ijk[0], ijk[1], ijk[2])) mine.append(i);
            }
            const labelList where(meshCellRanks(mesh, UIndirectList<point>(candidates, mine)(), true));
            label outsideMesh = 0;
            forAll(mine, k)
            {
                if (where[k] >= 0) continue;
                inside[mine[k]] = volumeType::OUTSIDE;
                ++outsideMesh;
            }
            Info<< "    left out " << returnReduce(outsideMesh, sumOp<label>())
                << " points outside the mesh" << nl;
        }

        // Points per source cell, counted by the rank owning it; their
        // global prefix numbers the points.
        labelList count(L.nCells[0]*L.nCells[1]*L.nCells[2], 0);
        forAll(sources, si)
        {
            if (!ml.ownsLatticeCell(sources[si])) continue;
            for (label q = 0; q < perCell; ++q) count[sources[si]] += inside[si*perCell + q] == volumeType::INSIDE;
        }
        if (Pstream::parRun())
        {
            Pstream::listCombineGather(count, plusEqOp<label>());
            Pstream::listCombineScatter(count);
        }
        labelList first(count.size(), 0);
        for (label i = 1; i < count.size(); ++i) first[i] = first[i - 1] + count[i - 1];
        const label regionTotal = count.empty() ? 0 : first.last() + count.last();

        forAll(sources, si)
        {
            label k = 0;
            for (label q = 0; q < perCell; ++q)
            {
                const label i = si*perCell + q;
                if (inside[i] != volumeType::INSIDE) continue;
                const label id = idBase + first[sources[si]] + k++;
                const point& x = candidates[i];
                label ijk[3];
                ml.indicesOf(x, ijk);
                if (!ml.ownsLatticeCell(ijk[0], ijk[1], ijk[2])) continue;   // another rank's
                const vector v(velocity(x));
                const mpm::Index p = points.add
                (
                    {x.x(), x.y(), x.z()}, {v.x(), v.y(), v.z()},
                    rho*solidFraction*pointVol, pointVol, int(mat)
                );
                points.id[p] = id;
                regionOf.push_back(regioni);
                points.sigma[mpm::XX][p] = sigma0.xx();
                points.sigma[mpm::YY][p] = sigma0.yy();
                points.sigma[mpm::ZZ][p] = sigma0.zz();
                points.sigma[mpm::XY][p] = sigma0.xy();
                points.sigma[mpm::YZ][p] = sigma0.yz();
                points.sigma[mpm::XZ][p] = sigma0.xz();
            }
        }
        idBase += regionTotal;
        Info<< "    " << regionTotal << " points of material "
            << materials.names()[mat] << ", " << ppc << " per cell" << nl;
        if (regionTotal == 0)
        {
            WarningInFunction << "Region " << name << " contains no points" << nl;
        }
    }
    reportTotals(points, n0, regionOf, regionNames, materials.names());
    return points.size() - n0;
}
