#include "surfaceWallShape.H"
#include "volumeType.H"
#include "polyMesh.H"
#include "mergePoints.H"
#include "boundBox.H"

Foam::closedSurface::closedSurface(const triSurface& s)
:
    surf_(s)
{
    search_.reset(new triSurfaceSearch(surf_));
    // Build the octree's cached inside/outside types and the normals now:
    // later queries only read
    search_->tree().getVolumeType(surf_.points()[0] + vector::one*1e-5);
    surf_.faceNormals();
}

bool Foam::closedSurface::inside(const point& p) const
{
    return search_->tree().getVolumeType(p) == volumeType::INSIDE;
}

Foam::surfaceWallShape::surfaceWallShape
(
    const triSurface& distance,
    const std::shared_ptr<const closedSurface>& sign,
    bool materialInside,
    const std::string& description
)
:
    sign_(sign),
    surf_(distance),
    materialInside_(materialInside),
    description_(description)
{
    search_.reset(new triSurfaceSearch(surf_));
    surf_.faceNormals();
}

mpm::Real Foam::surfaceWallShape::distance
(
    const mpm::Real x[3], mpm::Real normal[3], mpm::Real band
) const
{
    const point p(x[0], x[1], x[2]);
    // Positive on the material's side
    const scalar side = sign_->inside(p) == materialInside_ ? 1 : -1;
    const pointIndexHit hit = search_->nearest(p, vector::uniform(2*band));
    if (!hit.hit())
    {
        normal[0] = 0; normal[1] = 0; normal[2] = 1;
        return side*band;
    }
    const vector d(p - hit.hitPoint());
    const scalar m = mag(d);
    // Into the material: away from the surface on its side, towards it
    // from within the wall; on the surface, the triangle's normal (outward
    // of the closed surface) turned to the material's side
    const vector n
    (
        m > SMALL*(1 + mag(p))
      ? vector(side*d/m)
      : vector((materialInside_ ? -1 : 1)*surf_.faceNormals()[hit.index()])
    );
    for (direction a = 0; a < 3; ++a) normal[a] = n[a];
    return side*m;
}

Foam::triSurface Foam::triangulate(const polyMesh& mesh, const labelUList& faces)
{
    // This rank's triangles as corner triples
    DynamicList<point> corners;
    for (const label facei : faces)
    {
        const face& f = mesh.faces()[facei];
        for (label i = 1; i + 1 < f.size(); ++i)
        {
            corners.append(mesh.points()[f[0]]);
            corners.append(mesh.points()[f[i]]);
            corners.append(mesh.points()[f[i + 1]]);
        }
    }
    // Every rank's, on every rank
    List<pointField> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = corners;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    pointField pts;
    for (const pointField& p : all) pts.append(p);
    // Shared corners become shared points (the inside test looks at edges
    // and points near them)
    const boundBox bb(mesh.points(), true);
    labelList pointMap;
    pointField merged;
    mergePoints(pts, 1e-9*bb.mag(), false, pointMap, merged);
    List<labelledTri> tris(pts.size()/3);
    forAll(tris, t)
    {
        tris[t] = labelledTri(pointMap[3*t], pointMap[3*t + 1], pointMap[3*t + 2], 0);
    }
    return triSurface(tris, merged);
}
