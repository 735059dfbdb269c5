#include "io_vrml_flt.h"

#include "format_adapters.h"

#include "support/progress_lines.h"

namespace {
bool isVrml(const QString& format)
{
    const QString f = format.toUpper();
    // "GZ": MeshLab names a format by the last suffix, so x.wrl.gz arrives as "gz".
    return f == "WRL" || f == "WRZ" || f == "VRML" || f == "GZ";
}
bool isOpenFlight(const QString& format) { return format.toUpper() == "FLT"; }
}  // namespace

QString IoVrmlFltPlugin::pluginName() const { return "IOVrmlFlt"; }

QList<MeshIOInterface::Format> IoVrmlFltPlugin::importFormats() const
{
    return {Format("VRML 97 / VRML 1.0 CAD export (cadlod)", tr("WRL")),
            Format("VRML gzip (cadlod)", tr("WRZ")),
            Format("VRML (cadlod)", tr("VRML")),
            Format("VRML gzip, .wrl.gz (cadlod)", tr("GZ")),
            Format("OpenFlight (cadlod)", tr("FLT"))};
}

QList<MeshIOInterface::Format> IoVrmlFltPlugin::exportFormats() const
{
    return {Format("OpenFlight LOD model (cadlod)", tr("FLT"))};
}

void IoVrmlFltPlugin::GetExportMaskCapability(QString& format, int& capability, int& defaultBits) const
{
    capability = defaultBits = 0;
    if (isOpenFlight(format))
        capability = defaultBits = cadlod::fltExportCapability();
}

void IoVrmlFltPlugin::initPreOpenParameter(const QString& format, const QString&, RichParameterList& par)
{
    if (isVrml(format))
        cadlod::vrmlOpenParameters(par);
    else if (isOpenFlight(format))
        cadlod::fltOpenParameters(par);
}

void IoVrmlFltPlugin::initSaveParameter(const QString& format, MeshModel& m, RichParameterList& par)
{
    if (isOpenFlight(format))
        cadlod::fltSaveParameters(m, par);
}

bool IoVrmlFltPlugin::open(const QString& format, const QString& fileName, MeshModel& m, int& mask,
                           const RichParameterList& par, vcg::CallBackPos* cb, QWidget*)
{
    // MeshLab shows errorMessage after any open that logs or fails: a message left over
    // from an earlier failed save or open must not come back as a warning now.
    errorMessage.clear();
    cadlod::ProgressLines progress(cb);  // one line per step if a headless caller prints them
    if (isVrml(format))
        return cadlod::openVrml(*this, fileName, m, mask, par, progress.callback(), errorMessage);
    if (isOpenFlight(format))
        return cadlod::openOpenFlight(*this, fileName, m, mask, par, progress.callback(), errorMessage);
    errorMessage = "io_vrml_flt cannot open format " + format;
    return false;
}

bool IoVrmlFltPlugin::save(const QString& format, const QString& fileName, MeshModel& m, const int mask,
                           const RichParameterList& par, vcg::CallBackPos* cb, QWidget*)
{
    errorMessage.clear();
    cadlod::ProgressLines progress(cb);
    if (isOpenFlight(format))
        return cadlod::saveOpenFlight(*this, fileName, m, mask, par, progress.callback(), errorMessage);
    errorMessage = "io_vrml_flt cannot save format " + format;
    return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(IoVrmlFltPlugin)
