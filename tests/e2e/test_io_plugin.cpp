// The io_vrml_flt plugin as MeshLab loads it (QPluginLoader on the staged .so): what the
// GUI shows after open() and save() (errorMsg()).
#include <common/interfaces.h>
#include <common/meshmodel.h>
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QPluginLoader>
#include <QTemporaryDir>

#include <memory>
#include <string>
#include <vector>

namespace {

MeshIOInterface* stagedIoPlugin()
{
    static QPluginLoader loader(QString(CADLOD_STAGE_PLUGIN_DIR) + "/libio_vrml_flt.so");
    QObject* instance = loader.instance();
    EXPECT_NE(instance, nullptr) << loader.errorString().toStdString();
    return instance ? qobject_cast<MeshIOInterface*>(instance) : nullptr;
}

void addTriangle(MeshModel& m)
{
    auto v = vcg::tri::Allocator<CMeshO>::AddVertices(m.cm, 3);
    v[0].P() = {0, 0, 0};
    v[1].P() = {1, 0, 0};
    v[2].P() = {0, 1, 0};
    vcg::tri::Allocator<CMeshO>::AddFace(m.cm, &m.cm.vert[0], &m.cm.vert[1], &m.cm.vert[2]);
}

}  // namespace

// A failed save says why (errno text), and its message is not shown again as a warning
// by the next, successful open (issue 16, item 6).
TEST(IoPlugin, FailedSaveSaysWhyAndDoesNotHauntTheNextOpen)
{
    MeshIOInterface* plugin = stagedIoPlugin();
    ASSERT_NE(plugin, nullptr);
    QTemporaryDir dir;
    MeshDocument doc;
    MeshModel* m = doc.addNewMesh("", "tri");
    addTriangle(*m);
    QString format = "flt";
    RichParameterList savePar;
    plugin->initSaveParameter(format, *m, savePar);
    const QString bad = dir.filePath("no/such/dir/tri.flt");
    EXPECT_FALSE(plugin->save(format, bad, *m, 0, savePar, nullptr, nullptr));
    EXPECT_TRUE(plugin->errorMsg().contains("No such file or directory")) << plugin->errorMsg().toStdString();

    const QString good = dir.filePath("tri.flt");
    ASSERT_TRUE(plugin->save(format, good, *m, 0, savePar, nullptr, nullptr)) << plugin->errorMsg().toStdString();
    EXPECT_TRUE(plugin->errorMsg().isEmpty()) << plugin->errorMsg().toStdString();

    EXPECT_FALSE(plugin->save(format, bad, *m, 0, savePar, nullptr, nullptr));
    MeshModel* opened = doc.addNewMesh("", "opened");
    RichParameterList openPar;
    plugin->initPreOpenParameter(format, good, openPar);
    int mask = 0;
    ASSERT_TRUE(plugin->open(format, good, *opened, mask, openPar, nullptr, nullptr));
    EXPECT_TRUE(plugin->errorMsg().isEmpty()) << "stale: " << plugin->errorMsg().toStdString();
    EXPECT_EQ(opened->cm.fn, 1);
    for (MeshModel* layer : doc.meshList)
        layer->cm.ClearAttributes();
}

namespace {

struct ProgressCall {
    int pos;
    std::string what;
    qint64 ms;
};
std::vector<ProgressCall> g_calls;
QElapsedTimer g_clock;

bool recordProgress(const int pos, const char* what)
{
    g_calls.push_back({pos, what ? what : "", g_clock.elapsed()});
    return true;
}

}  // namespace

// The save ends with a progress call MeshLab does not drop (its callback ignores a call
// within 100 ms of the previous one, or at the same position), so the status bar says
// "OpenFlight saved" instead of keeping "Writing OpenFlight" (issue 16, item 12).
TEST(IoPlugin, SaveEndsWithAProgressCallMeshLabShows)
{
    MeshIOInterface* plugin = stagedIoPlugin();
    ASSERT_NE(plugin, nullptr);
    QTemporaryDir dir;
    MeshDocument doc;
    MeshModel* m = doc.addNewMesh("", "tri");
    addTriangle(*m);
    QString format = "flt";
    RichParameterList par;
    plugin->initSaveParameter(format, *m, par);
    g_calls.clear();
    g_clock.start();
    ASSERT_TRUE(plugin->save(format, dir.filePath("tri.flt"), *m, 0, par, recordProgress, nullptr));
    ASSERT_GE(g_calls.size(), 2u);
    const ProgressCall& last = g_calls.back();
    const ProgressCall& before = g_calls[g_calls.size() - 2];
    EXPECT_EQ(last.pos, 100);
    EXPECT_EQ(last.what, "OpenFlight saved\n");  // a line of its own when meshlabserver prints it
    EXPECT_LT(before.pos, 100);
    EXPECT_GE(last.ms - before.ms, 100);
    m->cm.ClearAttributes();
}
