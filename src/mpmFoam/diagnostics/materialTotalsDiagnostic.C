#include "materialTotalsDiagnostic.H"
#include "mpmModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(materialTotalsDiagnostic, 0);
    addToRunTimeSelectionTable(mpmDiagnostic, materialTotalsDiagnostic, dictionary);
}

void Foam::materialTotalsDiagnostic::report(Ostream& log)
{
    const mpm::Particles& P = mpm_.system().particles();
    const wordList& names = mpm_.materials().names();
    labelList count(names.size(), Zero);
    scalarList mass(names.size(), Zero);
    for (mpm::Index p = 0; p < P.size(); ++p)
    {
        ++count[P.material[p]];
        mass[P.material[p]] += P.mass[p];
    }
    Pstream::listCombineGather(count, plusEqOp<label>());
    Pstream::listCombineGather(mass, plusEqOp<scalar>());
    if (!Pstream::master()) return;

    log << "MPM: " << sum(count) << " points, mass " << sum(mass);
    if (names.size() > 1)
    {
        log << " (";
        forAll(names, m)
        {
            log << (m ? ", " : "") << names[m] << ' ' << count[m] << ' ' << mass[m];
        }
        log << ')';
    }
    log << nl;

    string header("# time points mass");
    for (const word& n : names) header += " points_" + n + " mass_" + n;
    OFstream& os = file("materialTotals", header + "\n");
    os << mpm_.mesh().time().value() << ' ' << sum(count) << ' ' << sum(mass);
    forAll(names, m) os << ' ' << count[m] << ' ' << mass[m];
    os << endl;
}
