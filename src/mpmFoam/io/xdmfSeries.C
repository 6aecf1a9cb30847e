#include "xdmfSeries.H"
#include "hdf5File.H"
#include "OSspecific.H"
#include <fstream>
#include <sstream>

namespace
{

std::string dims(const std::vector<std::uint64_t>& d)
{
    std::ostringstream os;
    for (std::size_t i = 0; i < d.size(); ++i) os << (i ? " " : "") << d[i];
    return os.str();
}

// A dataset's DataItem: its shape and number type read from the file
std::string dataItem(const Foam::hdf5File& h5, const std::string& ref, const std::string& set)
{
    int bytes = 8;
    const bool integer = h5.integer(set, bytes);
    std::ostringstream os;
    os  << "<DataItem Dimensions=\"" << dims(h5.shape(set)) << "\" NumberType=\""
        << (integer ? "Int" : "Float") << "\" Precision=\"" << bytes
        << "\" Format=\"HDF\">" << ref << ":" << set << "</DataItem>";
    return os.str();
}

const char* attributeType(std::int64_t comps)
{
    switch (comps)
    {
        case 3: return "Vector";
        case 6: return "Tensor6";   // xx xy xz yy yz zz
        case 9: return "Tensor";
        default: return "Scalar";
    }
}

} // namespace

void Foam::writeXdmfSeries
(
    const fileName& xmf,
    const List<Tuple2<scalar, fileName>>& files,
    const fileName& dataDir
)
{
    // One temporal collection per block (the points, the lattice), each
    // a grid per time: ParaView's XDMF Reader then names the blocks
    // materialPoints and lattice at every time (a temporal collection of
    // spatial ones gave materialPoints[1], [2], ... from the second time)
    std::ostringstream points, lattice;
    points.precision(17);
    lattice.precision(17);
    for (const auto& f : files)
    {
        const std::string ref = dataDir/f.second();
        const hdf5File h5(xmf.path()/dataDir/f.second(), hdf5File::mode::read, false);
        const std::uint64_t n = h5.int64Attribute("/materialPoints", "count").at(0);
        points
            << "<Grid Name=\"materialPoints\" GridType=\"Uniform\">\n"
            << "<Time Value=\"" << f.first() << "\"/>\n"
            << "<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
            << "\" NodesPerElement=\"1\"/>\n<Geometry GeometryType=\"XYZ\">"
            << dataItem(h5, ref, "/materialPoints/position") << "</Geometry>\n";
        const std::vector<std::string> names(h5.stringsAttribute("/materialPoints", "fields"));
        const std::vector<std::int64_t> comps(h5.int64Attribute("/materialPoints", "components"));
        for (std::size_t i = 0; i < names.size(); ++i)
        {
            if (names[i] == "position") continue;
            points
                << "<Attribute Name=\"" << names[i] << "\" AttributeType=\""
                << attributeType(comps[i]) << "\" Center=\"Node\">"
                << dataItem(h5, ref, "/materialPoints/" + names[i]) << "</Attribute>\n";
        }
        points << "</Grid>\n";
        // Lattice: XDMF gives CoRectMesh sizes and vectors slowest axis
        // first (z y x)
        const std::vector<std::int64_t> cells(h5.int64Attribute("/lattice", "cells"));
        const std::vector<double> origin(h5.doubleAttribute("/lattice", "origin"));
        const std::vector<double> spacing(h5.doubleAttribute("/lattice", "spacing"));
        lattice
            << "<Grid Name=\"lattice\" GridType=\"Uniform\">\n"
            << "<Time Value=\"" << f.first() << "\"/>\n"
            << "<Topology TopologyType=\"3DCoRectMesh\" Dimensions=\""
            << cells[2] + 1 << " " << cells[1] + 1 << " " << cells[0] + 1 << "\"/>\n"
            << "<Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
            << "<DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
            << origin[2] << " " << origin[1] << " " << origin[0] << "</DataItem>\n"
            << "<DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">"
            << spacing[2] << " " << spacing[1] << " " << spacing[0] << "</DataItem>\n"
            << "</Geometry>\n";
        const std::vector<std::string> cellNames(h5.stringsAttribute("/lattice", "fields"));
        const std::vector<std::int64_t> cellComps(h5.int64Attribute("/lattice", "components"));
        for (std::size_t i = 0; i < cellNames.size(); ++i)
        {
            lattice
                << "<Attribute Name=\"" << cellNames[i] << "\" AttributeType=\""
                << attributeType(cellComps[i]) << "\" Center=\"Cell\">"
                << dataItem(h5, ref, "/lattice/" + cellNames[i]) << "</Attribute>\n";
        }
        lattice << "</Grid>\n";
    }
    std::ostringstream os;
    os  << "<?xml version=\"1.0\" ?>\n"
        << "<!-- mpmFoam HDF5 checkpoints: open in ParaView with \"XDMF Reader\" -->\n"
        << "<Xdmf Version=\"2.0\">\n<Domain>\n"
        << "<Grid Name=\"materialPoints\" GridType=\"Collection\" CollectionType=\"Temporal\">\n"
        << points.str() << "</Grid>\n"
        << "<Grid Name=\"lattice\" GridType=\"Collection\" CollectionType=\"Temporal\">\n"
        << lattice.str() << "</Grid>\n"
        << "</Domain>\n</Xdmf>\n";

    const fileName tmp(xmf + ".tmp");
    {
        std::ofstream out(tmp);
        out << os.str();
        if (!out.good())
        {
            throw std::runtime_error("cannot write " + std::string(tmp));
        }
    }
    if (!Foam::mv(tmp, xmf))
    {
        throw std::runtime_error("cannot rename " + std::string(tmp));
    }
}
