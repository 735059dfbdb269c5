// The per-format halves of the io_vrml_flt plugin. Each function translates between a
// MeshLab layer and one of cadlod's MeshLab-independent cores, logs through `plugin`
// (MeshLabInterface::Log) and, on failure, returns false with `error` set. None of them
// may open a dialog: meshlabserver would block for ever.
#pragma once

#include <common/interfaces.h>

#include <QElapsedTimer>
#include <QThread>

#include <algorithm>
#include <cstdio>
#include <string>

namespace cadlod {

// Logs through the plugin and to stderr: meshlabserver's -i path never gives an IO plugin a
// log (MeshLabInterface::Log is then a no-op), so a report there would be lost.
inline void report(MeshIOInterface& plugin, GLLogStream::Levels level, const std::string& text)
{
    plugin.Log(level, text);
    std::fprintf(stderr, "io_vrml_flt: %s\n", text.c_str());
}
inline void report(MeshIOInterface& plugin, GLLogStream::Levels level, const QString& text)
{
    report(plugin, level, text.toStdString());
}

// Forwards progress to MeshLab's callback and ends with a message that stays in the status
// bar. MeshLab 2020.09's callback drops a call that comes within 100 ms of the one before
// or repeats its position, so a save that ends quickly would leave "Writing OpenFlight"
// on screen: the last call waits out those 100 ms and always has its own position.
class ProgressReporter {
public:
    explicit ProgressReporter(vcg::CallBackPos* cb) : cb_(cb) {}
    void operator()(int percent, const char* what)
    {
        if (!cb_)
            return;
        cb_(std::min(percent, 99), what);
        last_.start();
    }
    void finish(const char* what)
    {
        if (!cb_)
            return;
        if (last_.isValid() && last_.elapsed() < kGapMs)
            QThread::msleep(static_cast<unsigned long>(kGapMs - last_.elapsed()));
        cb_(100, what);
    }

private:
    static constexpr qint64 kGapMs = 110;
    vcg::CallBackPos* cb_;
    QElapsedTimer last_;
};

// VRML97 / VRML 1.0, plain or gzip (vrml_import.cpp).
void vrmlOpenParameters(RichParameterList& par);
bool openVrml(MeshIOInterface& plugin, const QString& fileName, MeshModel& m, int& mask,
              const RichParameterList& par, vcg::CallBackPos* cb, QString& error);

// OpenFlight (flt_import.cpp, flt_export.cpp).
void fltOpenParameters(RichParameterList& par);
bool openOpenFlight(MeshIOInterface& plugin, const QString& fileName, MeshModel& m, int& mask,
                    const RichParameterList& par, vcg::CallBackPos* cb, QString& error);
void fltSaveParameters(MeshModel& m, RichParameterList& par);
int fltExportCapability();
bool saveOpenFlight(MeshIOInterface& plugin, const QString& fileName, MeshModel& m, int mask,
                    const RichParameterList& par, vcg::CallBackPos* cb, QString& error);

}  // namespace cadlod
