#include "test_mesh.h"

#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_ply.h>

namespace cadlod::test {

bool loadPly(const std::string& path, TestMesh& m, int& mask, std::string& error)
{
    using Importer = vcg::tri::io::ImporterPLY<TestMesh>;
    mask = 0;
    const int rc = Importer::Open(m, path.c_str(), mask);
    if (rc != 0 && Importer::ErrorCritical(rc)) {
        error = path + ": " + Importer::ErrorMsg(rc);
        return false;
    }
    return true;
}

bool loadPly(const std::string& path, TestMesh& m)
{
    int mask = 0;
    std::string error;
    return loadPly(path, m, mask, error);
}

bool savePly(const std::string& path, TestMesh& m, int mask)
{
    return vcg::tri::io::ExporterPLY<TestMesh>::Save(m, path.c_str(), mask, true) == 0;
}

}  // namespace cadlod::test
