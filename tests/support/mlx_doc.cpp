// cadlod_mlx_doc PLUGIN_DIR OUT.md
//
// Writes the reference of every cadlod filter's .mlx parameters (docs/mlx-parameters.md)
// from the filters themselves: the plugins are loaded as meshlabserver loads them and each
// filter is asked for its parameter list, so the document cannot drift from the code (a
// test compares the committed file with a fresh one). Defaults that depend on the mesh
// are computed on a tetrahedron, as cadlod_mlx_complete does.
#include <common/interfaces.h>
#include <common/pluginmanager.h>

#include "plugin_host.h"


#include <QApplication>
#include <QDomDocument>
#include <QFile>
#include <QTextDocumentFragment>
#include <QTextStream>

#include <cstdio>

namespace {

// One line of Markdown: plain text (filter descriptions use HTML entities), no line
// breaks, no table-breaking bars.
QString cell(QString text)
{
    text = QTextDocumentFragment::fromHtml(text).toPlainText();
    text.replace('\n', ' ');
    text.replace('|', "\\|");
    return text.simplified();
}

// The value as a script writes it (the "value" attribute), enums with their choices.
QString valueOf(const RichParameter& rp, QDomDocument& doc)
{
    const QDomElement e = rp.fillToXMLDocument(doc, false);
    QString value = "`" + e.attribute("value") + "`";
    const int choices = e.attribute("enum_cardinality", "0").toInt();
    if (choices > 0) {
        QStringList names;
        for (int i = 0; i < choices; ++i)
            names << QString("%1 = %2").arg(i).arg(e.attribute(QString("enum_val%1").arg(i)));
        value += " (" + names.join("; ") + ")";
    }
    return value;
}

}  // namespace

int main(int argc, char** argv)
{
    qSetGlobalQHashSeed(0);
    QApplication app(argc, argv);
    if (argc != 3) {
        std::fprintf(stderr, "usage: cadlod_mlx_doc PLUGIN_DIR OUT.md\n");
        return 2;
    }
    cadlod::test::PluginHost host(argv[1]);
    PluginManager& pm = host.plugins;
    MeshDocument& md = host.document;

    QString text;
    QTextStream out(&text);
    out << "# .mlx parameter names of cadlod's filters\n\n"
        << "Generated from the filters by `scripts/make_mlx_doc.sh` (the tool "
           "`tests/support/mlx_doc.cpp`); the test `Docs.MlxParametersUpToDate` fails when this "
           "file and the filters differ. Do not edit by hand.\n\n"
        << "A script names a filter by its menu name and each parameter by its script name. "
           "Write only the parameters you change, then complete the script with "
           "`scripts/complete_mlx.sh short.mlx full.mlx` (meshlabserver 2020.09 needs every "
           "parameter, in order). Defaults that depend on the mesh (sizes, face counts) are shown "
           "for a tetrahedron; in a run they are computed on your mesh.\n\n"
        << "```xml\n<!DOCTYPE FilterScript>\n<FilterScript>\n"
        << " <filter name=\"Generate CAD LOD Set\">\n"
        << "  <Param name=\"...\" value=\"...\"/>\n </filter>\n</FilterScript>\n```\n";
    QDomDocument doc;
    int filters = 0;
    for (MeshFilterInterface* plugin : pm.meshFilterPlugins()) {
        if (plugin->pluginName() != "FilterCadLod")
            continue;
        for (QAction* action : plugin->actions()) {
            ++filters;
            RichParameterList params;
            plugin->initParameterSet(action, md, params);
            const QString name = plugin->filterName(action);
            out << "\n## " << name << "\n\n" << cell(plugin->filterInfo(action)) << "\n\n";
            if (params.isEmpty()) {
                out << "No parameters: `<filter name=\"" << name << "\"/>`.\n";
                continue;
            }
            out << "| script name | type | default | label | meaning |\n|---|---|---|---|---|\n";
            for (const RichParameter& rp : params)
                out << "| `" << rp.name() << "` | " << rp.stringType() << " | " << cell(valueOf(rp, doc)) << " | "
                    << cell(rp.fieldDescription()) << " | " << cell(rp.toolTip()) << " |\n";
        }
    }
    out.flush();
    if (filters == 0) {
        std::fprintf(stderr, "cadlod_mlx_doc: no cadlod filter in %s\n", argv[1]);
        return 1;
    }
    QFile file(argv[2]);
    if (!file.open(QIODevice::WriteOnly)) {
        std::fprintf(stderr, "cadlod_mlx_doc: cannot write %s\n", argv[2]);
        return 1;
    }
    file.write(text.toUtf8());
    return 0;
}
