// The MeshLab plugins of a directory loaded outside MeshLab, with a document holding one
// small mesh (a tetrahedron with every component), so that a tool can ask each filter for
// its parameters the way MeshLab's dialogs and meshlabserver do.
#pragma once

#include <common/interfaces.h>
#include <common/pluginmanager.h>

#include <vcg/complex/algorithms/create/platonic.h>

#include <QDir>

namespace cadlod::test {

struct PluginHost {
    PluginManager plugins;
    MeshDocument document;
    MeshModel* mesh = nullptr;

    explicit PluginHost(const QString& pluginDir)
    {
        RichParameterList globals;
        plugins.loadPlugins(globals, QDir(pluginDir));
        mesh = document.addNewMesh("", "dummy", true);
        vcg::tri::Tetrahedron<CMeshO>(mesh->cm);
        mesh->updateDataMask(MeshModel::MM_ALL);
    }
};

}  // namespace cadlod::test
