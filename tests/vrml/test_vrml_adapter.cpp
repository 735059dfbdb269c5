// The MeshLab adapter (io_vrml_flt/vrml_import.cpp) on a real CMeshO: part table and
// per-face part ids in the layer, open options (unit scale, merge, normals), errors.
#include "mesh/layer_metadata.h"
#include "format_adapters.h"

#include <common/meshmodel.h>
#include <gtest/gtest.h>

#include <QTemporaryDir>

#include <fstream>

namespace {

class NullIoPlugin : public MeshIOInterface {
public:
    QList<Format> importFormats() const override { return {}; }
    QList<Format> exportFormats() const override { return {}; }
    void GetExportMaskCapability(QString&, int&, int&) const override {}
    bool open(const QString&, const QString&, MeshModel&, int&, const RichParameterList&, vcg::CallBackPos*,
              QWidget*) override { return false; }
    bool save(const QString&, const QString&, MeshModel&, const int, const RichParameterList&, vcg::CallBackPos*,
              QWidget*) override { return false; }
};

// vcglib 2020.09's ~TriMesh leaves named attributes allocated (ClearAttributes is commented
// out there): the layers the adapter filled free theirs before the document deletes them.
class LayerAttributesRelease {
public:
    explicit LayerAttributesRelease(MeshDocument& doc) : doc_(doc) {}
    LayerAttributesRelease(const LayerAttributesRelease&) = delete;
    LayerAttributesRelease& operator=(const LayerAttributesRelease&) = delete;
    ~LayerAttributesRelease()
    {
        for (MeshModel* m : doc_.meshList) m->cm.ClearAttributes();
    }

private:
    MeshDocument& doc_;
};

struct Opened {
    bool ok = false;
    int mask = 0;
    QString error;
};

class VrmlAdapter : public ::testing::Test {
protected:
    std::string write(const std::string& name, const std::string& text)
    {
        const std::string path = dir_.filePath(QString::fromStdString(name)).toStdString();
        std::ofstream(path) << text;
        return path;
    }

    Opened open(const std::string& path, void (*tweak)(RichParameterList&) = nullptr)
    {
        RichParameterList par;
        cadlod::vrmlOpenParameters(par);
        if (tweak) tweak(par);
        m_ = doc_.addNewMesh(QString::fromStdString(path), "layer");
        Opened o;
        o.ok = cadlod::openVrml(plugin_, QString::fromStdString(path), *m_, o.mask, par, nullptr, o.error);
        return o;
    }

    QTemporaryDir dir_;
    MeshDocument doc_;
    LayerAttributesRelease release_{doc_};  // destroyed before doc_
    NullIoPlugin plugin_;
    MeshModel* m_ = nullptr;
};

const char* kAssembly = R"(#VRML V2.0 utf8
DEF Base Transform { children Shape {
  appearance Appearance { material Material { diffuseColor 1 0 0 } }
  geometry IndexedFaceSet { coord DEF P Coordinate { point [ 0 0 0, 1000 0 0, 1000 1000 0, 0 1000 0 ] }
    coordIndex [ 0 1 2 -1 ] } } }
DEF Lid Transform { children Shape {
  appearance Appearance { material Material { diffuseColor 0 0 1 } }
  geometry IndexedFaceSet { coord USE P coordIndex [ 0 2 3 -1 ] } } }
)";

}  // namespace

TEST_F(VrmlAdapter, PartsReachTheLayerAsTableAndPerFaceIds)
{
    const Opened o = open(write("asm.wrl", kAssembly));
    ASSERT_TRUE(o.ok) << o.error.toStdString();
    EXPECT_TRUE(o.mask & vcg::tri::io::Mask::IOM_FACECOLOR);
    ASSERT_TRUE(cadlod::hasParts(m_->cm));
    const cadlod::PartTable& table = cadlod::partTableHandle(m_->cm)();
    ASSERT_EQ(table.size(), 2u);
    EXPECT_EQ(table[0].name, "Base");
    EXPECT_EQ(table[1].name, "Lid");
    EXPECT_FLOAT_EQ(table[1].color[2], 1.0f);
    auto part = cadlod::facePartHandle(m_->cm);
    ASSERT_EQ(m_->cm.fn, 2);
    EXPECT_EQ(part[0], 0);
    EXPECT_EQ(part[1], 1);
    EXPECT_EQ(m_->cm.face[1].C(), vcg::Color4b(0, 0, 255, 255));
    EXPECT_EQ(m_->cm.vn, 4);  // the shared diagonal is welded by default
}

TEST_F(VrmlAdapter, UnitScaleAndMergeOptions)
{
    const Opened o = open(write("asm.wrl", kAssembly), [](RichParameterList& p) {
        p.setValue("vrmlUnitScale", FloatValue(0.001f));
        p.setValue("vrmlMergeVertices", BoolValue(false));
    });
    ASSERT_TRUE(o.ok);
    EXPECT_EQ(m_->cm.vn, 6);
    EXPECT_NEAR(m_->cm.bbox.max[0], 1.0f, 1e-6);
}

TEST_F(VrmlAdapter, MergeToleranceJoinsNearlyCoincidentPoints)
{
    const std::string text = "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point "
                             "[ 0 0 0, 1 0 0, 1 1 0, 0.0001 0 0, 1 1.0001 0, 0 1 0 ] } coordIndex [ 0 1 2 -1 3 4 5 ] } }";
    const Opened exact = open(write("near.wrl", text));
    ASSERT_TRUE(exact.ok);
    EXPECT_EQ(m_->cm.vn, 6);
    const Opened tolerant = open(write("near.wrl", text),
                                 [](RichParameterList& p) { p.setValue("vrmlMergeTolerance", FloatValue(0.001f)); });
    ASSERT_TRUE(tolerant.ok);
    EXPECT_EQ(m_->cm.vn, 4);
}

TEST_F(VrmlAdapter, NormalsModeKeepsOrRecomputes)
{
    const std::string text = "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point "
                             "[ 0 0 0, 1 0 0, 0 1 0 ] } coordIndex [ 0 1 2 ] normal Normal { vector [ 0 1 0 ] } "
                             "normalPerVertex FALSE } }";
    ASSERT_TRUE(open(write("n.wrl", text)).ok);
    EXPECT_EQ(m_->cm.vert[0].N(), vcg::Point3f(0, 1, 0));
    ASSERT_TRUE(open(write("n.wrl", text), [](RichParameterList& p) { p.setValue("vrmlNormals", EnumValue(1)); }).ok);
    EXPECT_EQ(m_->cm.vert[0].N(), vcg::Point3f(0, 0, 1));
}

TEST_F(VrmlAdapter, UnreadableFileFailsWithMessage)
{
    const Opened o = open(write("x.wrl", "ply\nformat ascii 1.0\n"));
    EXPECT_FALSE(o.ok);
    EXPECT_TRUE(o.error.contains("not a VRML file")) << o.error.toStdString();
    EXPECT_TRUE(o.error.contains("x.wrl"));
}

TEST_F(VrmlAdapter, InstancingBombFailsWithTheUseThatCrossesTheLimit)
{
    std::string text = "#VRML V2.0 utf8\nDEF L0 Shape { geometry Box {} }\n";
    for (int i = 1; i <= 7; ++i) {
        text += "DEF L" + std::to_string(i) + " Group { children [";
        for (int k = 0; k < 10; ++k) text += " USE L" + std::to_string(i - 1);
        text += " ] }\n";
    }
    const std::string path = write("bomb.wrl", text);
    const Opened o = open(path);
    EXPECT_FALSE(o.ok);
    EXPECT_EQ(o.error.toStdString(),
              path + ":9:48: USE L6 would make the scene exceed 50000000 triangles (instancing limit)");
    EXPECT_EQ(m_->cm.FN(), 0);
}

TEST_F(VrmlAdapter, TextureCoordinatesBecomeWedgeTexCoordsWithTheTexture)
{
    write("wood.png", "not really a png");
    const std::string text = R"(#VRML V2.0 utf8
Shape { appearance Appearance { texture ImageTexture { url "wood.png" } }
  geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] } coordIndex [ 0 1 2 ]
    texCoord TextureCoordinate { point [ 0 0, 1 0, 0 1 ] } } }
Shape { appearance Appearance { texture ImageTexture { url "gone.png" } } geometry Box {} }
)";
    const Opened o = open(write("tex.wrl", text));
    ASSERT_TRUE(o.ok);
    EXPECT_TRUE(o.mask & vcg::tri::io::Mask::IOM_WEDGTEXCOORD);
    ASSERT_EQ(m_->cm.textures.size(), 1u);
    EXPECT_NE(m_->cm.textures[0].find("wood.png"), std::string::npos);
    const CFaceO& f = m_->cm.face[0];
    EXPECT_EQ(f.cWT(1).N(), 0);
    EXPECT_FLOAT_EQ(f.cWT(1).U() + f.cWT(2).U(), 1.0f);
    EXPECT_FLOAT_EQ(f.cWT(1).V() + f.cWT(2).V(), 1.0f);
    EXPECT_EQ(m_->cm.face[1].cWT(0).N(), -1);  // the box: no texture (missing file)
}
