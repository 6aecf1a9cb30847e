#include "materialPointsIO.H"
#include "meshCellSearch.H"
#include "passiveParticleCloud.H"
#include "IOField.H"
#include "symmTensor.H"
#include "tensor.H"
#include "IOdictionary.H"
#include "ListOps.H"

const Foam::word Foam::materialPointsCloudName("materialPoints");

namespace
{

using namespace Foam;

// OpenFOAM's symmTensor is (xx xy xz yy yz zz); the core's is
// (xx yy zz xy yz xz).
const int symmToCore[6] = {mpm::XX, mpm::XY, mpm::XZ, mpm::YY, mpm::YZ, mpm::ZZ};

// Visits every per-point array with its OpenFOAM field name and type, so
// reading and writing share one list. `Real` arrays are scalar fields.
template<class Points, class Visitor>
void forEachField(Points& p, Visitor&& v)
{
    v.vectorField("U", p.v);
    v.scalarField("mass", p.mass);
    v.scalarField("volume", p.volume);
    v.scalarField("volume0", p.volume0);
    v.scalarField("plasticStrain", p.eqPlasticStrain);
    v.symmTensorField("stress", p.sigma);
    v.tensorField("F", p.F);
    v.tensorField("C", p.C);
}

struct Writer
{
    const passiveParticleCloud& cloud;
    label n;

    void scalarField(const char* name, const mpm::StaggeredArray<mpm::Real>& a) const
    {
        IOField<scalar> f(cloud.fieldIOobject(name, IOobject::NO_READ), n);
        forAll(f, i) f[i] = a[i];
        f.write(n > 0);
    }
    void vectorField(const char* name, const std::array<mpm::StaggeredArray<mpm::Real>, 3>& a) const
    {
        IOField<vector> f(cloud.fieldIOobject(name, IOobject::NO_READ), n);
        forAll(f, i) f[i] = vector(a[0][i], a[1][i], a[2][i]);
        f.write(n > 0);
    }
    void symmTensorField(const char* name, const std::array<mpm::StaggeredArray<mpm::Real>, 6>& a) const
    {
        IOField<symmTensor> f(cloud.fieldIOobject(name, IOobject::NO_READ), n);
        forAll(f, i) for (int c = 0; c < 6; ++c) f[i][c] = a[symmToCore[c]][i];
        f.write(n > 0);
    }
    void tensorField(const char* name, const std::array<mpm::StaggeredArray<mpm::Real>, 9>& a) const
    {
        IOField<tensor> f(cloud.fieldIOobject(name, IOobject::NO_READ), n);
        forAll(f, i) for (int c = 0; c < 9; ++c) f[i][c] = a[c][i];
        f.write(n > 0);
    }
};

struct Reader
{
    const passiveParticleCloud& cloud;
    label n;

    template<class Type>
    IOField<Type> read(const char* name) const
    {
        IOobject io(cloud.fieldIOobject(name, IOobject::MUST_READ));
        if (!io.typeHeaderOk<IOField<Type>>(true))
        {
            FatalErrorInFunction
                << "Material-point field " << name << " is missing in "
                << io.path() << nl << "If a run wrote this time, delete "
                << "it and restart from an earlier one; if it is the seeded "
                << "time, seed again with mpmSetParticles."
                << exit(FatalError);
        }
        IOField<Type> f(io);
        if (f.size() != n)
        {
            FatalErrorInFunction
                << "Material-point field " << io.objectPath() << " has "
                << f.size() << " values for " << n << " points"
                << exit(FatalError);
        }
        return f;
    }
    void scalarField(const char* name, mpm::StaggeredArray<mpm::Real>& a) const
    {
        const IOField<scalar> f(read<scalar>(name));
        forAll(f, i) a[i] = f[i];
    }
    void vectorField(const char* name, std::array<mpm::StaggeredArray<mpm::Real>, 3>& a) const
    {
        const IOField<vector> f(read<vector>(name));
        forAll(f, i) for (int c = 0; c < 3; ++c) a[c][i] = f[i][c];
    }
    void symmTensorField(const char* name, std::array<mpm::StaggeredArray<mpm::Real>, 6>& a) const
    {
        const IOField<symmTensor> f(read<symmTensor>(name));
        forAll(f, i) for (int c = 0; c < 6; ++c) a[symmToCore[c]][i] = f[i][c];
    }
    void tensorField(const char* name, std::array<mpm::StaggeredArray<mpm::Real>, 9>& a) const
    {
        const IOField<tensor> f(read<tensor>(name));
        forAll(f, i) for (int c = 0; c < 9; ++c) a[c][i] = f[i][c];
    }
};

// The material name table of a time's cloud
IOobject materialTableIO(const Time& runTime, IOobject::readOption r)
{
    return IOobject
    (
        "mpmMaterials", runTime.timeName(), "uniform", runTime, r,
        IOobject::NO_WRITE, false
    );
}

void writeMaterialTable(const Time& runTime, const wordList& names)
{
    IOdictionary table(materialTableIO(runTime, IOobject::NO_READ));
    table.note() = "the materials that the cloud's material index refers to";
    table.add("materials", names);
    table.regIOobject::write();
}

// cloud index -> index in `current`, from the table of the time; FatalIOError
// for a name `current` lacks, a warning when there is no table
labelList materialMap(const Time& runTime, const wordList& current)
{
    IOobject io(materialTableIO(runTime, IOobject::MUST_READ));
    if (!io.typeHeaderOk<IOdictionary>(true))
    {
        WarningInFunction
            << "No material name table " << runTime.timeName()/"uniform"
            /"mpmMaterials" << " (a cloud written before it existed): "
            << "assuming its material indices follow the current order of "
            << "constant/mpmProperties materials " << current << nl
            << "If materials were inserted or reordered since seeding, the "
            << "points now have another law: re-order mpmProperties." << endl;
        return identity(current.size());
    }
    const IOdictionary table(io);
    const wordList written(table.get<wordList>("materials"));
    labelList map(written.size());
    forAll(written, i)
    {
        map[i] = current.find(written[i]);
        if (map[i] < 0)
        {
            FatalIOErrorInFunction(table)
                << "The material points of time " << runTime.timeName()
                << " include material '" << written[i] << "', which "
                << "constant/mpmProperties materials does not define "
                << current << nl << "Add it back (or rename it there to '"
                << written[i] << "'): a point keeps its material by name."
                << exit(FatalIOError);
        }
    }
    if (map != identity(current.size()))
    {
        Info<< "Material points: materials mapped by name from the cloud's "
            << "table " << written << " to mpmProperties " << current << nl;
    }
    return map;
}

} // namespace

void Foam::writeMaterialPoints
(
    const fvMesh& mesh,
    const meshLattice& ml,
    const mpm::Particles& onOwners,
    const wordList& materialNames
)
{
    // Decomposed on a lattice of its own, a point is on the processor of its
    // lattice cell: the cloud is written per processor's mesh cells, so a
    // copy of the points goes there first (meshCellSearch.H)
    const bool move = Pstream::parRun() && !ml.ownersAreMeshRanks();
    mpm::Particles moved;
    if (move)
    {
        moved = onOwners;
        const label n = toMeshCellRanks(mesh, moved);
        Info<< "Material points: " << n << " written by the processor of"
            << " their mesh cell, not of their lattice cell" << nl;
    }
    const mpm::Particles& points = move ? moved : onOwners;
    passiveParticleCloud cloud(mesh, materialPointsCloudName, IDLList<passiveParticle>());
    const label n = points.size();
    // Locating particles builds the mesh's tet decomposition, and the cloud
    // writes its uniform properties, both collectively: every rank takes
    // part, with or without points. A rank without points writes no files
    // (as decomposePar), through write(valid = false).
    (void)mesh.tetBasePtIs();
    for (label p = 0; p < n; ++p)
    {
        const point x(points.x[0][p], points.x[1][p], points.x[2][p]);
        label celli = ml.fvCellOf(x);
        // Moved to the processor whose cells hold it, or whose box does
        // (a point a hair outside the mesh, on a wall): the nearest cell
        if (celli < 0 && move) celli = mesh.findNearestCell(x);
        if (celli < 0)
        {
            FatalErrorInFunction
                << "Material point " << label(points.id[p]) << " at " << x
                << " is not in a cell of processor " << Pstream::myProcNo()
                << exit(FatalError);
        }
        cloud.addParticle(new passiveParticle(mesh, x, celli));
    }
    cloud.write();

    forEachField(points, Writer{cloud, n});

    IOField<scalar> J(cloud.fieldIOobject("J", IOobject::NO_READ), n);
    forAll(J, i) J[i] = points.J(i);
    J.write(n > 0);
    IOField<label> mat(cloud.fieldIOobject("material", IOobject::NO_READ), n);
    forAll(mat, i) mat[i] = points.material[i];
    mat.write(n > 0);
    IOField<label> id(cloud.fieldIOobject("pointId", IOobject::NO_READ), n);
    forAll(id, i) id[i] = label(points.id[i]);
    id.write(n > 0);
    writeMaterialTable(mesh.time(), materialNames);
}

void Foam::readMaterialPoints
(
    const fvMesh& mesh,
    mpm::Particles& points,
    const wordList& materialNames
)
{
    (void)mesh.tetBasePtIs();     // collective: before any rank needs it
    passiveParticleCloud cloud(mesh, materialPointsCloudName);
    const label n = cloud.size();
    if (returnReduce(n, sumOp<label>()) == 0)
    {
        FatalErrorInFunction
            << "No material points in " << mesh.time().timePath()/cloud::prefix
            /materialPointsCloudName << nl
            << "Seed them with mpmSetParticles (system/mpmSetParticlesDict)."
            << exit(FatalError);
    }
    // Collective (the table is read by every rank), before any returns
    const labelList map
    (
        materialNames.empty() ? labelList() : materialMap(mesh.time(), materialNames)
    );
    points.resize(n);
    if (n == 0) return;     // a decomposed rank may have none
    label i = 0;
    for (const passiveParticle& p : cloud)
    {
        const point x(p.position());
        for (int c = 0; c < 3; ++c) points.x[c][i] = x[c];
        ++i;
    }
    const Reader reader{cloud, n};
    forEachField(points, reader);
    const IOField<label> mat(reader.read<label>("material"));
    const IOField<label> id(reader.read<label>("pointId"));
    forAll(mat, j)
    {
        points.id[j] = id[j];
        points.material[j] = mat[j];
        if (map.empty()) continue;
        if (mat[j] < 0 || mat[j] >= map.size())
        {
            FatalErrorInFunction
                << "Material point " << id[j] << " has material index "
                << mat[j] << ", but the cloud's material table "
                << mesh.time().timeName()/"uniform"/"mpmMaterials" << " has "
                << map.size() << " materials" << exit(FatalError);
        }
        points.material[j] = map[mat[j]];
    }
}
