#include "hdf5MaterialPoints.H"
#include "meshCellSearch.H"
#include "hdf5File.H"
#include "xdmfSeries.H"
#include "materialPointsIO.H"
#include "cloud.H"
#include "volFields.H"
#include "OSspecific.H"
#include "OStringStream.H"
#include "addToRunTimeSelectionTable.H"
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace Foam
{
    defineTypeNameAndDebug(hdf5MaterialPoints, 0);
    addToRunTimeSelectionTable(materialPointsFormat, hdf5MaterialPoints, mesh);
}

namespace
{

using namespace Foam;

const std::string points = "/materialPoints/";
const std::string lattice = "/lattice/";
const char* const formatTag = "mpmFoam materialPoints 1";
const word filePrefix("materialPoints_");   // + time name + ".h5"

// Symmetric tensors in the file: xx xy xz yy yz zz, the order of XDMF's
// Tensor6 (ParaView's XDMF reader expands it to the full tensor from that
// order) and of OpenFOAM's symmTensor; the core's is xx yy zz xy yz xz.
const int symmFileToCore[6] = {mpm::XX, mpm::XY, mpm::XZ, mpm::YY, mpm::YZ, mpm::ZZ};

// Every real per-point array, with its dataset name, components (file
// component c is core array order[c]; nullptr: the same), units and
// meaning: one list for writing and reading, so a new field is one line.
template<class P, class Fn>
void forEachRealField(P& p, Fn&& f)
{
    f("position", p.x.data(), 3, nullptr, "m", "position (x y z)");
    f("U", p.v.data(), 3, nullptr, "m/s", "velocity");
    f("mass", &p.mass, 1, nullptr, "kg", "mass");
    f("volume", &p.volume, 1, nullptr, "m^3", "current volume (J volume0)");
    f("volume0", &p.volume0, 1, nullptr, "m^3", "initial volume");
    f("stress", p.sigma.data(), 6, symmFileToCore, "Pa",
        "Cauchy stress, symmetric: xx xy xz yy yz zz (XDMF Tensor6, OpenFOAM)");
    f("F", p.F.data(), 9, nullptr, "1", "deformation gradient, row-major");
    f("C", p.C.data(), 9, nullptr, "1/s", "APIC affine velocity matrix, row-major");
    f("plasticStrain", &p.eqPlasticStrain, 1, nullptr, "1", "equivalent plastic strain (history)");
}

// Row-major rows of n points x cols components, and back
std::vector<double> rows(const mpm::StaggeredArray<mpm::Real>* a, int cols, const int* order, label n)
{
    std::vector<double> out(std::size_t(n)*cols);
    for (label p = 0; p < n; ++p)
    {
        for (int c = 0; c < cols; ++c)
        {
            out[std::size_t(p)*cols + c] = a[order ? order[c] : c][p];
        }
    }
    return out;
}

void unrows(const std::vector<double>& in, mpm::StaggeredArray<mpm::Real>* a, int cols, const int* order, label n)
{
    for (label p = 0; p < n; ++p)
    {
        for (int c = 0; c < cols; ++c)
        {
            a[order ? order[c] : c][p] = in[std::size_t(p)*cols + c];
        }
    }
}

std::string dimensionsText(const dimensionSet& d)
{
    OStringStream os;
    os << d;
    return os.str() + " (kg m s K mol A cd)";
}

// Throws an HDF5 failure as OpenFOAM's FatalError
template<class Fn>
void guarded(const char* what, Fn&& fn)
{
    try
    {
        fn();
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction << what << ": " << e.what() << exit(FatalError);
    }
}

} // namespace

Foam::fileName Foam::hdf5MaterialPoints::directory(const Time& runTime)
{
    return runTime.globalPath()/"HDF5";
}

Foam::List<Foam::Tuple2<Foam::scalar, Foam::fileName>>
Foam::hdf5MaterialPoints::checkpoints(const Time& runTime)
{
    // Only the final names count: a write in progress (or killed) is
    // <name>.tmp
    DynamicList<Tuple2<scalar, fileName>> found;
    for (const fileName& f : readDir(directory(runTime), fileName::FILE))
    {
        if (f.ext() != "h5" || !f.startsWith(filePrefix)) continue;
        const word t(f.lessExt().substr(filePrefix.size()));
        scalar value;
        if (readScalar(t, value)) found.append({value, f});
    }
    List<Tuple2<scalar, fileName>> sorted(found);
    std::sort(sorted.begin(), sorted.end(),
        [](const Tuple2<scalar, fileName>& a, const Tuple2<scalar, fileName>& b)
        { return a.first() < b.first(); });
    return sorted;
}

void Foam::hdf5MaterialPoints::write(const mpm::Particles& P)
{
    writeFile(P, filePrefix + mesh_.time().timeName() + ".h5");
}

namespace
{
    const Foam::word seededName("seededPoints.h5");
}

void Foam::hdf5MaterialPoints::writeStart(const mpm::Particles& P)
{
    if (readCloud_) writeFile(P, seededName);
}

void Foam::hdf5MaterialPoints::writeSeries(const Time& runTime) const
{
    List<Tuple2<scalar, fileName>> files(checkpoints(runTime));
    const fileName seed(directory(runTime)/seededName);
    if (isFile(seed))
    {
        // Its time, from the file: before the first checkpoint, or left out
        const scalar t = hdf5File(seed, hdf5File::mode::read, false).doubleAttribute("/", "time").at(0);
        if (files.empty() || t < files.first().first())
        {
            List<Tuple2<scalar, fileName>> all(1, Tuple2<scalar, fileName>(t, seededName));
            all.append(files);
            files.transfer(all);
        }
    }
    writeXdmfSeries(runTime.globalPath()/"materialPoints.xmf", files, "HDF5");
}

void Foam::hdf5MaterialPoints::writeFile(const mpm::Particles& P, const word& name)
{
    const Time& runTime = mesh_.time();
    const fileName dir(directory(runTime));
    const fileName final(dir/name);
    const fileName tmp(final + ".tmp");
    if (Pstream::master()) mkDir(dir);
    comm_.sum(std::int64_t(0));   // the directory exists before anyone opens

    const label n = P.size();
    std::vector<std::int64_t> perRank;
    comm_.allGather({std::int64_t(n)}, perRank);
    std::uint64_t total = 0, offset = 0;
    for (int r = 0; r < int(perRank.size()); ++r)
    {
        if (r == comm_.rank()) offset = total;
        total += perRank[r];
    }

    guarded("Writing material points", [&]
    {
        hdf5File h5(tmp, hdf5File::mode::create, Pstream::parRun());
        h5.attribute("/", "format", std::string(formatTag));
        h5.attribute("/", "time", std::vector<double>{runTime.value()});
        h5.attribute("/", "timeName", std::string(runTime.timeName()));
        h5.attribute("/", "timeIndex", std::vector<std::int64_t>{runTime.timeIndex()});
        h5.attribute("/", "materialNames",
            std::vector<std::string>(materialNames_.begin(), materialNames_.end()));
        h5.attribute("/", "pointsPerRank", perRank);

        h5.createGroup(points);
        h5.attribute(points, "count", std::vector<std::int64_t>{std::int64_t(total)});
        std::vector<std::string> names;
        std::vector<std::int64_t> comps;
        auto described = [&](const std::string& name, int cols, const char* units, const char* what)
        {
            h5.attribute(points + name, "units", std::string(units));
            h5.attribute(points + name, "description", std::string(what));
            names.push_back(name);
            comps.push_back(cols);
        };
        forEachRealField(P, [&](const char* name, const mpm::StaggeredArray<mpm::Real>* a,
            int cols, const int* order, const char* units, const char* what)
        {
            h5.writeRows(points + name, total, cols > 1 ? cols : 0, offset, rows(a, cols, order, n));
            described(name, cols, units, what);
        });
        std::vector<double> J(n);
        for (label p = 0; p < n; ++p) J[p] = P.J(p);
        h5.writeRows(points + "J", total, 0, offset, J);
        described("J", 1, "1", "volume ratio det F (post-processing)");
        h5.writeRows(points + "material", total, 0, offset, std::vector<int>(P.material.begin(), P.material.end()));
        described("material", 1, "1", "index into the file's materialNames");
        h5.writeRows(points + "pointId", total, 0, offset, P.id);
        described("pointId", 1, "1", "stable point id");
        h5.attribute(points, "fields", names);
        h5.attribute(points, "components", comps);

        // The lattice fields: every volField the run writes
        const mpm::Lattice& L = lattice_.lattice();
        h5.createGroup(lattice);
        std::vector<double> origin(3), spacing(3);
        std::vector<std::int64_t> cells(3);
        for (int d = 0; d < 3; ++d)
        {
            origin[d] = L.origin[d];
            spacing[d] = lattice_.cellSpan(d);
            cells[d] = L.nCells[d];
        }
        h5.attribute(lattice, "origin", origin);
        h5.attribute(lattice, "spacing", spacing);
        h5.attribute(lattice, "cells", cells);
        const std::vector<std::uint64_t> dims
            {std::uint64_t(cells[2]), std::uint64_t(cells[1]), std::uint64_t(cells[0])};
        // The master writes each cell field whole: it gathers the ranks'
        // cells (lattice index, then values), NaN where no mesh cell is.
        // Element-wise collective writes of scattered cells took longer
        // than the points (MPI-IO datatypes of one element each).
        const std::size_t nLattice = std::size_t(cells[0]*cells[1]*cells[2]);
        labelList cellIds(mesh_.nCells());
        forAll(lattice_.cellIndices(), celli)
        {
            const auto& r = lattice_.cellIndices()[celli];
            // A cell beyond the lattice's extent has no lattice cell
            cellIds[celli] = lattice_.cellInLattice(celli) ? label(L.cellIndex(r[0], r[1], r[2])) : -1;
        }
        List<labelList> allIds(Pstream::nProcs());
        allIds[Pstream::myProcNo()] = cellIds;
        Pstream::gatherList(allIds);
        std::vector<std::string> cellNames;
        std::vector<std::int64_t> cellComps;
        auto writeCellField = [&](const auto& fld, int cols)
        {
            using Type = typename std::decay<decltype(fld.primitiveField())>::type;
            List<Type> allValues(Pstream::nProcs());
            allValues[Pstream::myProcNo()] = fld.primitiveField();
            Pstream::gatherList(allValues);
            std::vector<double> v;
            if (Pstream::master())
            {
                v.assign(nLattice*cols, std::numeric_limits<double>::quiet_NaN());
                forAll(allIds, proc)
                {
                    forAll(allIds[proc], i)
                    {
                        if (allIds[proc][i] < 0) continue;
                        const scalar* x = reinterpret_cast<const scalar*>(&allValues[proc][i]);
                        std::copy(x, x + cols, v.begin() + std::size_t(allIds[proc][i])*cols);
                    }
                }
            }
            const std::string name = lattice + std::string(fld.name());
            h5.writeArray(name, dims, cols > 1 ? cols : 0, Pstream::master(), v);
            h5.attribute(name, "dimensions", dimensionsText(fld.dimensions()));
            cellNames.push_back(fld.name());
            cellComps.push_back(cols);
        };
        for (const word& f : mesh_.sortedNames<volScalarField>())
        {
            const volScalarField& fld = mesh_.lookupObject<volScalarField>(f);
            if (fld.writeOpt() == IOobject::AUTO_WRITE) writeCellField(fld, 1);
        }
        for (const word& f : mesh_.sortedNames<volVectorField>())
        {
            const volVectorField& fld = mesh_.lookupObject<volVectorField>(f);
            if (fld.writeOpt() == IOobject::AUTO_WRITE) writeCellField(fld, 3);
        }
        h5.attribute(lattice, "fields", cellNames);
        h5.attribute(lattice, "components", cellComps);
        h5.close();
    });

    // Complete on every rank: only now does the file get its final name
    comm_.sum(std::int64_t(0));
    if (Pstream::master())
    {
        if (!Foam::mv(tmp, final))
        {
            FatalErrorInFunction
                << "Cannot rename " << tmp << " to " << final << exit(FatalError);
        }
        guarded("Writing the XDMF series", [&] { writeSeries(runTime); });
    }
}

void Foam::hdf5MaterialPoints::read(mpm::Particles& P)
{
    const Time& runTime = mesh_.time();
    const List<Tuple2<scalar, fileName>> saved(checkpoints(runTime));
    const scalar tol = 1e-9*max(runTime.deltaTValue(), SMALL);
    const word startFrom(runTime.controlDict().lookupOrDefault<word>("startFrom", "latestTime"));

    // A re-decomposed case's processor directories start at 0 again: never
    // let latestTime silently restart from the seeded cloud
    // The time name of a checkpoint, as its file gives it
    auto nameOf = [](const fileName& f) { return word(f.lessExt().substr(filePrefix.size())); };
    if (startFrom == "latestTime" && saved.size() && saved.last().first() > runTime.value() + tol)
    {
        FatalErrorInFunction
            << "startFrom latestTime gives time " << runTime.timeName()
            << ", but there is a later HDF5 checkpoint at time "
            << nameOf(saved.last().second()) << " ("
            << directory(runTime)/saved.last().second() << ")." << nl
            << "To continue from it set 'startFrom startTime; startTime "
            << nameOf(saved.last().second()) << ";' in system/controlDict;"
            << " to start again remove " << directory(runTime) << "."
            << exit(FatalError);
    }

    fileName file;
    for (const auto& s : saved)
    {
        if (mag(s.first() - runTime.value()) <= tol) file = directory(runTime)/s.second();
    }
    if (file.empty())
    {
        const bool cloud = returnReduce
        (
            isDir(runTime.timePath()/cloud::prefix/materialPointsCloudName), orOp<bool>()
        );
        if (!cloud)
        {
            FatalErrorInFunction
                << "No HDF5 checkpoint for time " << runTime.timeName() << " ("
                << directory(runTime)/(filePrefix + runTime.timeName() + ".h5")
                << ") and no lagrangian cloud in " << runTime.timePath() << nl;
            if (saved.size())
            {
                FatalError
                    << "The last complete checkpoint is time " << nameOf(saved.last().second())
                    << ": set 'startFrom startTime; startTime " << nameOf(saved.last().second())
                    << ";' in system/controlDict to continue from it.";
            }
            else
            {
                FatalError
                    << "Seed the points with mpmSetParticles.";
            }
            FatalError << exit(FatalError);
        }
        // The points seeded by mpmSetParticles (or a run switched to hdf5)
        Info<< "No HDF5 checkpoint at time " << runTime.timeName()
            << ": reading the lagrangian cloud" << nl;
        readMaterialPoints(mesh_, P, materialNames_);
        if (!lattice_.ownersAreMeshRanks()) toLatticeOwners(lattice_, P);
        readCloud_ = true;
        return;
    }

    Info<< "Reading the material points of " << file << nl;
    readFile(file, P);
    // Points of this rank's cells stay where they are (all of them when the
    // processor count is the writer's); the others go to their owners
    toLatticeOwners(lattice_, P);
}

void Foam::hdf5MaterialPoints::readFile(const fileName& file, mpm::Particles& P) const
{
    guarded("Reading material points", [&]
    {
        hdf5File h5(file, hdf5File::mode::read, Pstream::parRun());
        if (h5.stringAttribute("/", "format") != formatTag)
        {
            throw std::runtime_error("not an mpmFoam checkpoint (format "
                + h5.stringAttribute("/", "format") + ")");
        }
        const std::int64_t total = h5.int64Attribute(points, "count").at(0);
        const std::vector<std::int64_t> written(h5.int64Attribute("/", "pointsPerRank"));
        const int np = comm_.size(), me = comm_.rank();

        // The writing run's slices when the processor count matches (each
        // rank then gets its own points back, in order); even slices else
        std::uint64_t offset = 0, n = 0;
        if (int(written.size()) == np)
        {
            for (int r = 0; r < me; ++r) offset += written[r];
            n = written[me];
        }
        else
        {
            offset = std::uint64_t(total)*me/np;
            n = std::uint64_t(total)*(me + 1)/np - offset;
        }

        P.resize(label(n));
        forEachRealField(P, [&](const char* name, mpm::StaggeredArray<mpm::Real>* a,
            int cols, const int* order, const char*, const char*)
        {
            std::vector<double> buf;
            h5.readRows(points + name, offset, n, buf);
            if (buf.size() != n*cols)
            {
                throw std::runtime_error(std::string("dataset ") + name
                    + " has the wrong number of components");
            }
            unrows(buf, a, cols, order, label(n));
        });
        h5.readRows(points + "pointId", offset, n, P.id);

        // Materials by name: the file's index -> mpmProperties' index
        const std::vector<std::string> names(h5.stringsAttribute("/", "materialNames"));
        std::vector<int> toLibrary(names.size(), -1);
        for (std::size_t m = 0; m < names.size(); ++m)
        {
            toLibrary[m] = materialNames_.find(word(names[m]));
        }
        std::vector<int> mat;
        h5.readRows(points + "material", offset, n, mat);
        for (std::uint64_t p = 0; p < n; ++p)
        {
            if (mat[p] < 0 || mat[p] >= int(names.size()) || toLibrary[mat[p]] < 0)
            {
                throw std::runtime_error("point " + std::to_string(P.id[p])
                    + " has material '" + (mat[p] >= 0 && mat[p] < int(names.size())
                    ? names[mat[p]] : std::to_string(mat[p]))
                    + "', which constant/mpmProperties does not define");
            }
            P.material[p] = toLibrary[mat[p]];
        }
        h5.close();
    });
}

