#include "hdf5File.H"
#include <mpi.h>
#include <hdf5.h>
#include <stdexcept>

namespace
{

template<class T> hid_t memType();
template<> hid_t memType<double>() { return H5T_NATIVE_DOUBLE; }
template<> hid_t memType<int>() { return H5T_NATIVE_INT; }
template<> hid_t memType<std::int64_t>() { return H5T_NATIVE_INT64; }

// Closes an HDF5 handle of any kind at scope exit.
struct handle
{
    hid_t id;
    herr_t (*closer)(hid_t);
    handle(hid_t i, herr_t (*c)(hid_t)) : id(i), closer(c) {}
    ~handle() { if (id >= 0) closer(id); }
    operator hid_t() const { return id; }
    handle(const handle&) = delete;
};

// Where the attribute lives: an object opened by name, "/" the file.
hid_t openObject(hid_t file, const std::string& obj)
{
    return H5Oopen(file, obj.c_str(), H5P_DEFAULT);
}

// Selects rows [offset, offset + n) of a [rows, width] file space (none when
// n = 0: a rank without rows still takes part) and returns the matching
// memory space
hid_t selectRows(hid_t fileSpace, int rank, hsize_t offset, hsize_t n, hsize_t width)
{
    hsize_t start[2] = {offset, 0}, count[2] = {n, width};
    if (n > 0) H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, start, nullptr, count, nullptr);
    else H5Sselect_none(fileSpace);
    const hid_t mem = H5Screate_simple(rank, count, nullptr);
    if (n == 0) H5Sselect_none(mem);
    return mem;
}

hid_t stringType(std::size_t size = H5T_VARIABLE)
{
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, size);
    H5Tset_cset(t, H5T_CSET_UTF8);
    return t;
}

} // namespace

bool Foam::hdf5File::parallelCapable()
{
#ifdef H5_HAVE_PARALLEL
    return true;
#else
    return false;
#endif
}

Foam::hdf5File::hdf5File(const std::string& path, mode m, bool parallel)
:
    path_(path),
    parallel_(parallel)
{
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    xfer_ = H5Pcreate(H5P_DATASET_XFER);
    if (parallel_)
    {
#ifdef H5_HAVE_PARALLEL
        H5Pset_fapl_mpio(fapl, MPI_COMM_WORLD, MPI_INFO_NULL);
        H5Pset_dxpl_mpio(xfer_, H5FD_MPIO_COLLECTIVE);
        // Metadata (attributes, dataset creation) identical on every rank
        H5Pset_all_coll_metadata_ops(fapl, true);
        H5Pset_coll_metadata_write(fapl, true);
#else
        fail("this HDF5 library has no MPI-IO (install libhdf5-openmpi-dev)");
#endif
    }
    file_ = m == mode::create
        ? H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl)
        : H5Fopen(path_.c_str(), H5F_ACC_RDONLY, fapl);
    if (file_ < 0)
    {
        fail(m == mode::create ? "cannot create the file" : "cannot open the file (not HDF5, or incomplete)");
    }
}

Foam::hdf5File::~hdf5File()
{
    if (file_ >= 0) H5Fclose(file_);
    if (xfer_ >= 0) H5Pclose(xfer_);
}

void Foam::hdf5File::close()
{
    const hid_t f = file_;
    file_ = -1;
    // Flushes every buffer: a full disk shows here
    if (f >= 0 && H5Fclose(f) < 0) fail("closing (writing the last data) failed; is the disk full?");
}

void Foam::hdf5File::fail(const std::string& what) const
{
    throw std::runtime_error("HDF5 file " + path_ + ": " + what);
}

void Foam::hdf5File::createGroup(const std::string& name)
{
    const hid_t g = H5Gcreate2(file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (g < 0) fail("cannot create group " + name);
    H5Gclose(g);
}

bool Foam::hdf5File::exists(const std::string& name) const
{
    return H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0;
}

template<class T>
void Foam::hdf5File::writeRows
(
    const std::string& name, std::uint64_t totalRows, int cols,
    std::uint64_t offset, const std::vector<T>& local
)
{
    const int rank = cols > 0 ? 2 : 1;
    const std::uint64_t width = cols > 0 ? std::uint64_t(cols) : 1;
    const std::uint64_t n = local.size()/width;
    hsize_t dims[2] = {totalRows, width};
    handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
    handle set
    (
        H5Dcreate2(file_, name.c_str(), memType<T>(), space,
            H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        H5Dclose
    );
    if (set < 0) fail("cannot create dataset " + name);
    handle mem(selectRows(space, rank, offset, n, width), H5Sclose);
    if (H5Dwrite(set, memType<T>(), mem, space, xfer_, local.data()) < 0)
    {
        fail("writing dataset " + name + " failed; is the disk full?");
    }
}

template<class T>
void Foam::hdf5File::readRows
(
    const std::string& name, std::uint64_t offset, std::uint64_t n,
    std::vector<T>& local
) const
{
    handle set(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (set < 0) fail("dataset " + name + " is missing");
    handle space(H5Dget_space(set), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space);
    hsize_t dims[2] = {0, 1};
    H5Sget_simple_extent_dims(space, dims, nullptr);
    if (rank < 1 || rank > 2 || offset + n > dims[0])
    {
        fail("dataset " + name + " has the wrong shape");
    }
    const hsize_t width = rank == 2 ? dims[1] : 1;
    local.resize(n*width);
    handle mem(selectRows(space, rank, offset, n, width), H5Sclose);
    if (H5Dread(set, memType<T>(), mem, space, xfer_, local.data()) < 0)
    {
        fail("reading dataset " + name + " failed");
    }
}

std::vector<std::uint64_t> Foam::hdf5File::shape(const std::string& name) const
{
    handle set(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (set < 0) fail("dataset " + name + " is missing");
    handle space(H5Dget_space(set), H5Sclose);
    hsize_t dims[8];
    const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
    return std::vector<std::uint64_t>(dims, dims + (rank > 0 ? rank : 0));
}

bool Foam::hdf5File::integer(const std::string& name, int& bytes) const
{
    handle set(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (set < 0) fail("dataset " + name + " is missing");
    handle type(H5Dget_type(set), H5Tclose);
    bytes = int(H5Tget_size(type));
    return H5Tget_class(type) == H5T_INTEGER;
}

void Foam::hdf5File::writeArray
(
    const std::string& name, const std::vector<std::uint64_t>& dims,
    int comps, bool writer, const std::vector<double>& values
)
{
    std::vector<hsize_t> d(dims.begin(), dims.end());
    if (comps > 0) d.push_back(hsize_t(comps));
    handle space(H5Screate_simple(int(d.size()), d.data(), nullptr), H5Sclose);
    handle set
    (
        H5Dcreate2(file_, name.c_str(), H5T_NATIVE_DOUBLE, space,
            H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        H5Dclose
    );
    if (set < 0) fail("cannot create dataset " + name);
    handle mem(H5Screate_simple(int(d.size()), d.data(), nullptr), H5Sclose);
    if (!writer)
    {
        H5Sselect_none(space);
        H5Sselect_none(mem);
    }
    if (H5Dwrite(set, H5T_NATIVE_DOUBLE, mem, space, xfer_, writer ? values.data() : nullptr) < 0)
    {
        fail("writing dataset " + name + " failed; is the disk full?");
    }
}

void Foam::hdf5File::attribute(const std::string& obj, const std::string& name, const std::string& value)
{
    handle o(openObject(file_, obj), H5Oclose);
    handle t(stringType(value.size() + 1), H5Tclose);
    handle space(H5Screate(H5S_SCALAR), H5Sclose);
    handle a(H5Acreate2(o, name.c_str(), t, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (a < 0 || H5Awrite(a, t, value.c_str()) < 0) fail("cannot write attribute " + obj + " " + name);
}

void Foam::hdf5File::attribute(const std::string& obj, const std::string& name, const std::vector<std::string>& value)
{
    handle o(openObject(file_, obj), H5Oclose);
    handle t(stringType(), H5Tclose);
    const hsize_t n = value.size();
    handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
    handle a(H5Acreate2(o, name.c_str(), t, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    std::vector<const char*> ptrs;
    for (const std::string& s : value) ptrs.push_back(s.c_str());
    if (a < 0 || H5Awrite(a, t, ptrs.data()) < 0) fail("cannot write attribute " + obj + " " + name);
}

void Foam::hdf5File::attribute(const std::string& obj, const std::string& name, const std::vector<double>& value)
{
    handle o(openObject(file_, obj), H5Oclose);
    const hsize_t n = value.size();
    handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
    handle a(H5Acreate2(o, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (a < 0 || H5Awrite(a, H5T_NATIVE_DOUBLE, value.data()) < 0) fail("cannot write attribute " + obj + " " + name);
}

void Foam::hdf5File::attribute(const std::string& obj, const std::string& name, const std::vector<std::int64_t>& value)
{
    handle o(openObject(file_, obj), H5Oclose);
    const hsize_t n = value.size();
    handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
    handle a(H5Acreate2(o, name.c_str(), H5T_NATIVE_INT64, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (a < 0 || H5Awrite(a, H5T_NATIVE_INT64, value.data()) < 0) fail("cannot write attribute " + obj + " " + name);
}

namespace
{

// Opens attribute obj/name, and gives its element count.
hid_t openAttribute(hid_t file, const std::string& obj, const std::string& name, hsize_t& n)
{
    n = 0;
    const hid_t o = openObject(file, obj);
    if (o < 0) return -1;
    const hid_t a = H5Aopen(o, name.c_str(), H5P_DEFAULT);
    H5Oclose(o);
    if (a < 0) return -1;
    handle space(H5Aget_space(a), H5Sclose);
    const hssize_t count = H5Sget_simple_extent_npoints(space);
    n = count > 0 ? hsize_t(count) : 0;
    return a;
}

} // namespace

std::string Foam::hdf5File::stringAttribute(const std::string& obj, const std::string& name) const
{
    hsize_t n;
    handle a(openAttribute(file_, obj, name, n), H5Aclose);
    if (a < 0 || n != 1) fail("attribute " + obj + " " + name + " is missing");
    handle t(H5Aget_type(a), H5Tclose);
    if (H5Tis_variable_str(t) > 0)
    {
        char* s = nullptr;
        handle vt(stringType(), H5Tclose);
        if (H5Aread(a, vt, &s) < 0) fail("cannot read attribute " + name);
        std::string out(s ? s : "");
        H5free_memory(s);
        return out;
    }
    std::string buf(H5Tget_size(t), '\0');
    handle ft(stringType(buf.size()), H5Tclose);
    if (H5Aread(a, ft, &buf[0]) < 0) fail("cannot read attribute " + name);
    return std::string(buf.c_str());
}

std::vector<std::string> Foam::hdf5File::stringsAttribute(const std::string& obj, const std::string& name) const
{
    hsize_t n;
    handle a(openAttribute(file_, obj, name, n), H5Aclose);
    if (a < 0) fail("attribute " + obj + " " + name + " is missing");
    std::vector<char*> ptrs(n, nullptr);
    handle t(stringType(), H5Tclose);
    if (n > 0 && H5Aread(a, t, ptrs.data()) < 0) fail("cannot read attribute " + name);
    std::vector<std::string> out;
    for (char* s : ptrs) { out.emplace_back(s ? s : ""); H5free_memory(s); }
    return out;
}

std::vector<double> Foam::hdf5File::doubleAttribute(const std::string& obj, const std::string& name) const
{
    hsize_t n;
    handle a(openAttribute(file_, obj, name, n), H5Aclose);
    if (a < 0) fail("attribute " + obj + " " + name + " is missing");
    std::vector<double> out(n);
    if (n > 0 && H5Aread(a, H5T_NATIVE_DOUBLE, out.data()) < 0) fail("cannot read attribute " + name);
    return out;
}

std::vector<std::int64_t> Foam::hdf5File::int64Attribute(const std::string& obj, const std::string& name) const
{
    hsize_t n;
    handle a(openAttribute(file_, obj, name, n), H5Aclose);
    if (a < 0) fail("attribute " + obj + " " + name + " is missing");
    std::vector<std::int64_t> out(n);
    if (n > 0 && H5Aread(a, H5T_NATIVE_INT64, out.data()) < 0) fail("cannot read attribute " + name);
    return out;
}

// The element types the checkpoints use
#define INSTANTIATE(T) \
    template void Foam::hdf5File::writeRows<T>(const std::string&, std::uint64_t, int, std::uint64_t, const std::vector<T>&); \
    template void Foam::hdf5File::readRows<T>(const std::string&, std::uint64_t, std::uint64_t, std::vector<T>&) const;
INSTANTIATE(double)
INSTANTIATE(int)
INSTANTIATE(std::int64_t)
#undef INSTANTIATE
