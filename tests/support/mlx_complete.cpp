// cadlod_mlx_complete [--drop-unknown] PLUGIN_DIR IN.mlx OUT.mlx
//
// meshlabserver 2020.09 only runs a filter script that lists every parameter of every
// filter, in the filter's own order (it asserts on anything shorter). This tool loads the
// plugins, asks each filter of IN.mlx for its parameter list (defaults computed on a
// tetrahedron, as MeshLab's own parameter map does), overrides the values IN.mlx gives, and
// writes the complete script. An unknown filter or parameter name is an error (exit 2), so
// a typo in a script is caught before meshlabserver runs. With --drop-unknown, a parameter
// the filter does not define (one an older version had) is dropped with a warning instead:
// for bringing an old complete script up to date, where a typo cannot be told from it.
#include <common/filterscript.h>
#include <common/interfaces.h>
#include <common/pluginmanager.h>

#include "plugin_host.h"


#include <QApplication>
#include <QDomDocument>
#include <QFile>
#include <QHash>
#include <QSet>
#include <QTextStream>

#include <cstdio>

namespace {

int fail(const QString& message)
{
    std::fprintf(stderr, "cadlod_mlx_complete: %s\n", qUtf8Printable(message));
    return 2;
}

bool readXml(const QString& path, QDomDocument& doc, QString& error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        error = path + ": cannot open";
        return false;
    }
    QString msg;
    int line = 0, column = 0;
    if (!doc.setContent(&file, false, &msg, &line, &column)) {
        error = QString("%1:%2:%3: %4").arg(path).arg(line).arg(column).arg(msg);
        return false;
    }
    return true;
}

// Copies every attribute of `given` but name and type onto `full`.
void overrideValue(QDomElement& full, const QDomElement& given)
{
    const QDomNamedNodeMap attributes = given.attributes();
    for (int i = 0; i < attributes.count(); ++i) {
        const QDomAttr a = attributes.item(i).toAttr();
        if (a.name() != "name" && a.name() != "type")
            full.setAttribute(a.name(), a.value());
    }
}

// A given parameter the filter does not define: an error, or with `dropUnknown` a warning.
bool refuseOrDrop(const QString& filter, const QString& param, const QSet<QString>& known, bool dropUnknown,
                  QString& error)
{
    if (dropUnknown) {
        std::fprintf(stderr, "cadlod_mlx_complete: warning: filter \"%s\" has no parameter \"%s\": dropped\n",
                     qUtf8Printable(filter), qUtf8Printable(param));
        return true;
    }
    QStringList names(known.begin(), known.end());
    names.sort();
    error = "filter \"" + filter + "\" has no parameter \"" + param + "\" (it has: " + names.join(", ") + ")";
    return false;
}

bool completeFilter(PluginManager& pm, MeshDocument& md, const QDomElement& given, bool dropUnknown,
                    QDomDocument& out, QDomElement& root, QString& error)
{
    const QString name = given.attribute("name");
    QAction* action = pm.actionFilterMap.value(name);
    if (!action) {
        error = "no filter named \"" + name + "\" in the plugins";
        return false;
    }
    RichParameterList defaults;
    pm.stringFilterMap[name]->initParameterSet(action, md, defaults);

    QMap<QString, QDomElement> givenParams;
    for (QDomElement p = given.firstChildElement("Param"); !p.isNull(); p = p.nextSiblingElement("Param"))
        givenParams[p.attribute("name")] = p;
    QDomElement filter = out.createElement("filter");
    filter.setAttribute("name", name);
    QSet<QString> known;
    for (const RichParameter& rp : defaults) {
        QDomElement param = rp.fillToXMLDocument(out, false);
        if (givenParams.contains(rp.name()))
            overrideValue(param, givenParams[rp.name()]);
        filter.appendChild(param);
        known.insert(rp.name());
    }
    for (const QString& p : givenParams.keys())
        if (!known.contains(p) && !refuseOrDrop(name, p, known, dropUnknown, error))
            return false;
    root.appendChild(filter);
    return true;
}

}  // namespace

int main(int argc, char** argv)
{
    qSetGlobalQHashSeed(0);  // the same attribute order every run
    QApplication app(argc, argv);
    QStringList args = app.arguments().mid(1);
    const bool dropUnknown = !args.isEmpty() && args.first() == "--drop-unknown";
    if (dropUnknown)
        args.removeFirst();
    if (args.size() != 3)
        return fail("usage: cadlod_mlx_complete [--drop-unknown] PLUGIN_DIR IN.mlx OUT.mlx");
    const QString pluginDir = args[0], inPath = args[1], outPath = args[2];

    QDomDocument in;
    QString error;
    if (!readXml(inPath, in, error))
        return fail(error);

    cadlod::test::PluginHost host(pluginDir);
    PluginManager& pm = host.plugins;
    MeshDocument& md = host.document;

    QDomDocument out("FilterScript");
    QDomElement root = out.createElement("FilterScript");
    out.appendChild(root);
    const QDomElement script = in.documentElement();
    for (QDomElement f = script.firstChildElement("filter"); !f.isNull(); f = f.nextSiblingElement("filter"))
        if (!completeFilter(pm, md, f, dropUnknown, out, root, error))
            return fail(inPath + ": " + error);

    QFile file(outPath);
    if (!file.open(QIODevice::WriteOnly))
        return fail(outPath + ": cannot write");
    QTextStream stream(&file);
    out.save(stream, 1);
    return 0;
}
