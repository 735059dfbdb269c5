// Loaded into the staged MeshLab with LD_PRELOAD by the GUI tests (gui_dialogs.sh,
// gui_lod_set.sh). It drives MeshLab through its own widgets (menu actions, dialog
// buttons), as a user would with the mouse, and writes what the user would see to the file
// named by CADLOD_GUI_PROBE_OUT, one fact per line; the test scripts judge the facts.
// CADLOD_GUI_PROBE names the scenario (see scenario() below), CADLOD_GUI_PROBE_DIR a
// scratch directory for files it saves.
//
// Widgets are found by what the user sees (window titles, button texts, action texts);
// MeshLab's document and views by class name, read through MeshLab's own headers.
// MeshLab's view headers first: they need GLEW before any other OpenGL header.
#include <GL/glew.h>
#include <glarea.h>
#include <multiViewer_Container.h>

#include "gui_probe_steps.h"

#include <QApplication>
#include <QDesktopWidget>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMessageBox>
#include <QMenu>
#include <QPlainTextEdit>
#include <QPointer>
#include <QPushButton>
#include <QScreen>
#include <QStatusBar>
#include <QTextBlock>
#include <QTextLayout>
#include <QTime>
#include <QRegularExpression>
#include <QTextDocument>
#include <QTreeWidget>

#include <cstdio>
#include <memory>

namespace cadlod_probe {
namespace {

QFile g_out;

void fact(const QString& line)
{
    if (qEnvironmentVariableIsSet("CADLOD_GUI_PROBE_TRACE"))
        std::fprintf(stderr, "probe %s: %s\n", qUtf8Printable(QTime::currentTime().toString("mm:ss.zzz")), qUtf8Printable(line));
    g_out.write(line.toUtf8() + "\n");
    g_out.flush();
}

QString plainText(const QLabel* label)
{
    QTextDocument doc;
    doc.setHtml(label->text());
    return doc.toPlainText().simplified();
}

QMainWindow* mainWindow()
{
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* m = qobject_cast<QMainWindow*>(w); m && QString(w->metaObject()->className()) == "MainWindow")
            return m;
    return nullptr;
}

template <class T>
T* findByClass(const char* className)
{
    QMainWindow* main = mainWindow();
    if (!main)
        return nullptr;
    for (QWidget* w : main->findChildren<QWidget*>())
        if (QString(w->metaObject()->className()) == className)
            return static_cast<T*>(w);
    return nullptr;
}

MeshDocument* document()
{
    auto* container = findByClass<MultiViewer_Container>("MultiViewer_Container");
    return container ? &container->meshDoc : nullptr;
}

GLArea* view() { return findByClass<GLArea>("GLArea"); }

// An entry of MeshLab's menus (plugins own their filters' actions, the menus list them).
QAction* actionNamed(const QString& text)
{
    QMainWindow* main = mainWindow();
    if (!main)
        return nullptr;
    for (QMenu* menu : main->findChildren<QMenu*>())
        for (QAction* a : menu->actions())
            if (QString(a->text()).remove('&') == text)
                return a;
    return nullptr;
}

QWidget* visibleWindowTitled(const QString& title)
{
    for (QWidget* w : QApplication::allWidgets())
        if (w->isVisible() && w->windowTitle() == title && (w->isWindow() || qobject_cast<QDockWidget*>(w)))
            return w;
    return nullptr;
}

// The shown top-level dialog that `is` accepts (QApplication::activeModalWidget() stays
// empty for a dialog MeshLab opens before its main loop runs).
template <class Predicate>
QDialog* visibleDialog(Predicate is)
{
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* d = qobject_cast<QDialog*>(w); d && d->isVisible() && is(d))
            return d;
    return nullptr;
}

template <class Button>
Button* buttonNamed(QWidget* root, const QString& text)
{
    for (Button* b : root->findChildren<Button*>())
        if (QString(b->text()).remove('&') == text && b->isVisible())
            return b;
    return nullptr;
}

// Every word-wrapped label of `root` (the help texts, the filter's description) must show
// its whole text: the height its text needs at its width fits in its own height, in what
// its parents leave visible of it, and on the screen.
void inspectHelpTexts(QWidget* root, const QString& name)
{
    const QRect screen = QApplication::desktop()->screenGeometry(root);
    int labels = 0;
    for (QLabel* label : root->findChildren<QLabel*>()) {
        if (!label->isVisible() || !label->wordWrap() || plainText(label).isEmpty())
            continue;
        ++labels;
        const int needs = label->heightForWidth(label->width());
        const QRect shown = label->visibleRegion().boundingRect();
        const QRect onScreen = QRect(label->mapToGlobal(QPoint(0, 0)), label->size()).intersected(screen);
        const int has = std::min({label->height(), shown.height(), onScreen.height()});
        if (needs > has || shown.width() < label->width())
            fact(QString("clipped %1 | %2 | needs %3 px, shows %4 of %5 px")
                     .arg(name, plainText(label).left(70))
                     .arg(needs)
                     .arg(has)
                     .arg(label->height()));
    }
    fact(QString("inspected %1: %2 texts").arg(name).arg(labels));
    const QString shots = qEnvironmentVariable("CADLOD_GUI_PROBE_SHOTS");
    if (!shots.isEmpty())
        QGuiApplication::primaryScreen()->grabWindow(0).save(shots + "/" + QString(name).replace(QRegularExpression("\\W+"), "_") + ".png");
}

// The next modal dialog titled `title`, with its help shown (its Help button or box),
// inspected and then accepted or rejected.
Step modalHelpCheck(const QString& title, const QString& name, bool accept)
{
    auto helpShown = std::make_shared<bool>(false);
    return [=]() {
        QDialog* dialog = visibleDialog([&](QDialog* d) { return d->windowTitle() == title; });
        if (!dialog)
            return false;
        if (!*helpShown) {
            if (auto* help = buttonNamed<QAbstractButton>(dialog, "Help"))
                help->click();
            *helpShown = true;
            return false;  // let the layout settle for one tick
        }
        inspectHelpTexts(dialog, name);
        if (accept)
            dialog->accept();
        else
            dialog->reject();
        return true;
    };
}

// A filter's dialog (MeshLab's dock "MeshlabStdDialog"), opened from its menu action.
QWidget* filterDock(const QString& filter) { return visibleWindowTitled(filter); }

Step openFilter(const QString& filter)
{
    return [=]() {
        if (filterDock(filter))
            return true;
        QAction* action = actionNamed(filter);
        if (!action)
            return false;
        action->trigger();
        return filterDock(filter) != nullptr;
    };
}

Step filterHelpCheck(const QString& filter)
{
    auto helpShown = std::make_shared<bool>(false);
    return [=]() {
        QWidget* dock = filterDock(filter);
        if (!dock)
            return false;
        if (!*helpShown) {
            if (auto* help = buttonNamed<QPushButton>(dock, "Help"))
                help->click();
            *helpShown = true;
            return false;
        }
        inspectHelpTexts(dock, filter);
        if (auto* close = buttonNamed<QPushButton>(dock, "Close"))
            close->click();
        return true;
    };
}

Step applyFilter(const QString& filter)
{
    return [=]() {
        QWidget* dock = filterDock(filter);
        auto* apply = dock ? buttonNamed<QPushButton>(dock, "Apply") : nullptr;
        if (!apply)
            return false;
        apply->click();  // runs the filter before it returns
        if (auto* close = buttonNamed<QPushButton>(dock, "Close"))
            close->click();
        fact("applied " + filter);
        return true;
    };
}

bool meshLoaded(int layers)
{
    MeshDocument* doc = document();
    return doc && doc->meshList.size() >= layers && !doc->isBusy() && !visibleDialog([](QDialog*) { return true; });
}

Step waitForLayers(int layers)
{
    return [=]() { return meshLoaded(layers); };
}

Step statusBarFact(const QString& when)
{
    return [=]() {
        QMainWindow* main = mainWindow();
        fact(QString("status %1: %2").arg(when, main ? main->statusBar()->currentMessage().trimmed() : "?"));
        return true;
    };
}

// The layers as the document has them and as the view draws them, and whether each name
// fits in the layer panel's column.
Step layerFacts()
{
    return [=]() {
        MeshDocument* doc = document();
        GLArea* glarea = view();
        if (!doc || !glarea)
            return false;
        for (MeshModel* m : doc->meshList)
            fact(QString("layer %1 | %2 | visible %3 | drawn %4")
                     .arg(m->id())
                     .arg(m->label())
                     .arg(m->visible ? 1 : 0)
                     .arg(glarea->meshVisibilityMap.value(m->id(), false) ? 1 : 0));
        for (QTreeWidget* tree : mainWindow()->findChildren<QTreeWidget*>()) {
            if (!tree->isVisible())
                continue;
            for (int i = 0; i < tree->topLevelItemCount(); ++i) {
                QTreeWidgetItem* item = tree->topLevelItem(i);
                for (int c = 0; c < tree->columnCount(); ++c) {
                    const QString text = item->text(c);
                    if (text.isEmpty() || text.toInt() != 0 || text == "0")
                        continue;
                    const int needs = tree->fontMetrics().horizontalAdvance(text);
                    const int has = tree->visualItemRect(item).isValid() ? tree->columnWidth(c) : 0;
                    fact(QString("panel %1 | needs %2 px, column %3 px").arg(text).arg(needs).arg(has));
                }
            }
        }
        return true;
    };
}

// Layers that appear in the document while a filter runs (sampled every tick).
Step watchLayers(const QString& word)
{
    return [=]() {
        if (MeshDocument* doc = document())
            for (MeshModel* m : doc->meshList)
                if (m->label().contains(word))
                    fact("seen while running: " + m->label());
        return true;
    };
}

Step makeCurrentLast()
{
    return [=]() {
        MeshDocument* doc = document();
        if (!doc || doc->meshList.isEmpty())
            return false;
        doc->setCurrentMesh(doc->meshList.back()->id());
        return true;
    };
}

// Where each bar (run of '#') of each log line that starts like a histogram bin
// ("0.3-0.4") begins, in px, as the log panel lays it out (lines without a bar are left
// out).
Step histogramFacts()
{
    return [=]() {
        QPlainTextEdit* log = nullptr;
        for (QPlainTextEdit* e : mainWindow()->findChildren<QPlainTextEdit*>())
            if (e->objectName() == "logPlainTextEdit")
                log = e;
        if (!log)
            return false;
        const QRegularExpression bin("^\\W*0\\.\\d-[01]\\.\\d");
        int lines = 0;
        for (QTextBlock b = log->document()->begin(); b.isValid(); b = b.next()) {
            QTextLayout* layout = b.layout();
            if (!layout)
                continue;
            for (int l = 0; l < layout->lineCount(); ++l) {
                const QTextLine line = layout->lineAt(l);
                const QString text = b.text().mid(line.textStart(), line.textLength());
                if (!bin.match(text).hasMatch())
                    continue;
                QStringList starts;
                for (int i = 0; i < text.size(); ++i)
                    if (text[i] == '#' && (i == 0 || text[i - 1] != '#'))
                        starts << QString::number(line.cursorToX(line.textStart() + i), 'f', 1);
                if (starts.isEmpty())
                    continue;
                fact("histogram " + starts.join(' ') + " | " + text.simplified());
                ++lines;
            }
        }
        return lines > 0;
    };
}

QLineEdit* fileNameEdit(QFileDialog* dialog) { return dialog->findChild<QLineEdit*>("fileNameEdit"); }

// Types `path` into the dialog's name field, as a user would: typing clears the list's
// selection, so the dialog takes the typed name.
void typeFileName(QFileDialog* dialog, const QString& path)
{
    if (QLineEdit* edit = fileNameEdit(dialog)) {
        edit->setFocus();
        edit->setText(path);
    } else {
        dialog->selectFile(path);
    }
}

// The dialog's own question whether to replace a file: Yes for `path` itself; No for any
// other file, so that none is replaced and the name can be typed again. False: none asked.
bool answerReplaceQuestion(QFileDialog* dialog, const QString& path)
{
    for (auto* box : dialog->findChildren<QMessageBox*>()) {
        if (!box->isVisible())
            continue;
        if (box->text().contains(QFileInfo(path).fileName())) {
            box->button(QMessageBox::Yes)->click();
        } else {
            fact("export dialog asked: " + QString(box->text()).replace('\n', ' ') + " (answered No)");
            box->button(QMessageBox::No)->click();
        }
        return true;
    }
    return false;
}

// Presses the dialog's button once it would take `path`, until it closes. A dialog still
// listing its folder may select the file it proposed when the listing arrives, after the
// name was typed; so the name is typed again until the dialog's own answer is `path`, and
// a question to replace the proposed file is answered No.
void acceptWhenChosen(QPointer<QFileDialog> dialog, const QString& path, int triesLeft)
{
    if (!dialog || !dialog->isVisible() || triesLeft == 0)
        return;
    if (!answerReplaceQuestion(dialog, path) && QApplication::activeModalWidget() == dialog.data()) {
        const QStringList chosen = dialog->selectedFiles();
        if (chosen.size() == 1 && QFileInfo(chosen.front()) == QFileInfo(path))
            static_cast<QDialog*>(dialog.data())->accept();
        else
            typeFileName(dialog, path);
    }
    QTimer::singleShot(300, [dialog, path, triesLeft]() { acceptWhenChosen(dialog, path, triesLeft - 1); });
}

// Chooses the file and presses the dialog's button, later: the dialog may ask more in a
// loop of its own, which must not run inside a step.
void chooseFile(QFileDialog* dialog, const QString& path)
{
    typeFileName(dialog, path);
    QTimer::singleShot(300, dialog, [dialog, path]() { acceptWhenChosen(dialog, path, 100); });
}

// Export Mesh As: what the file dialog proposes (folder and name); it is then cancelled,
// or, with `saveAs` given, that file is chosen.
Step exportDialogFacts(const QString& saveAs)
{
    auto triggered = std::make_shared<bool>(false);
    return [=]() {
        if (!*triggered) {
            QAction* action = actionNamed("Export Mesh As...");
            if (!action)
                return false;
            *triggered = true;
            QTimer::singleShot(0, action, &QAction::trigger);  // exec() returns only later
            return false;
        }
        auto* dialog = static_cast<QFileDialog*>(visibleDialog([](QDialog* d) { return qobject_cast<QFileDialog*>(d); }));
        if (!dialog)
            return false;
        fact(QString("export proposes folder %1 | name %2")
                 .arg(dialog->directory().absolutePath(), fileNameEdit(dialog)->text()));
        if (saveAs.isEmpty())
            dialog->reject();
        else
            chooseFile(dialog, saveAs);
        return true;
    };
}

Step importFile(const QString& path)
{
    auto triggered = std::make_shared<bool>(false);
    return [=]() {
        if (!*triggered) {
            QAction* action = actionNamed("Import Mesh...");
            if (!action)
                return false;
            *triggered = true;
            QTimer::singleShot(0, action, &QAction::trigger);
            return false;
        }
        auto* dialog = static_cast<QFileDialog*>(visibleDialog([](QDialog* d) { return qobject_cast<QFileDialog*>(d); }));
        if (!dialog)
            return false;
        chooseFile(dialog, path);
        return true;
    };
}

// The save options of Export Mesh As (MeshLab's SaveMaskExporterDialog, its Help box).
Step saveOptionsHelpCheck(const QString& name)
{
    auto helpShown = std::make_shared<bool>(false);
    return [=]() {
        QDialog* dialog = visibleDialog(
            [](QDialog* d) { return QString(d->metaObject()->className()) == "SaveMaskExporterDialog"; });
        if (!dialog)
            return false;
        if (!*helpShown) {
            if (auto* help = buttonNamed<QAbstractButton>(dialog, "Help"))
                help->click();
            *helpShown = true;
            return false;
        }
        inspectHelpTexts(dialog, name);
        if (auto* ok = buttonNamed<QAbstractButton>(dialog, "OK"))
            ok->click();
        else
            dialog->accept();
        return true;
    };
}

Steps scenario(const QString& name, const QString& dir)
{
    const QString flt = dir + "/probe.flt";
    if (name == "dialogs")
        return {modalHelpCheck("Pre-Open Options", "VRML open options", true),
                waitForLayers(1),
                openFilter("Simplification: CAD Quadric Edge Collapse (compactness)"),
                filterHelpCheck("Simplification: CAD Quadric Edge Collapse (compactness)"),
                openFilter("Generate CAD LOD Set"),
                filterHelpCheck("Generate CAD LOD Set"),
                openFilter("Simplification Report"),
                filterHelpCheck("Simplification Report"),
                exportDialogFacts(flt),
                saveOptionsHelpCheck("OpenFlight save options"),
                importFile(flt),
                modalHelpCheck("Pre-Open Options", "OpenFlight open options", true),
                waitForLayers(2)};
    if (name == "lodset")
        return {modalHelpCheck("Pre-Open Options", "VRML open options", true),
                waitForLayers(1),
                statusBarFact("after open"),
                exportDialogFacts(""),
                openFilter("Generate CAD LOD Set"),
                applyFilter("Generate CAD LOD Set"),
                layerFacts(),
                makeCurrentLast(),
                openFilter("Simplification Report"),
                applyFilter("Simplification Report"),
                histogramFacts(),
                exportDialogFacts("")};
    return {};
}

void start()
{
    const QString name = qEnvironmentVariable("CADLOD_GUI_PROBE");
    if (name.isEmpty())
        return;
    g_out.setFileName(qEnvironmentVariable("CADLOD_GUI_PROBE_OUT", "gui_probe.txt"));
    if (!g_out.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        std::fprintf(stderr, "gui_probe: cannot write %s\n", qUtf8Printable(g_out.fileName()));
        return;
    }
    Steps steps = scenario(name, qEnvironmentVariable("CADLOD_GUI_PROBE_DIR", "."));
    if (steps.empty()) {
        fact("unknown scenario " + name);
        return;
    }
    Steps watchers;
    if (name == "lodset")
        watchers.push_back(watchLayers("scratch"));
    runSteps(std::move(steps), std::move(watchers), [](const QString& line) { fact(line); });
}

}  // namespace
}  // namespace cadlod_probe

namespace {
void startProbe() { cadlod_probe::start(); }
}  // namespace
// Runs when MeshLab constructs its QApplication (the library is preloaded before).
Q_COREAPP_STARTUP_FUNCTION(startProbe)
