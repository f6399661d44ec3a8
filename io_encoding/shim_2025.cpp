// MeshLab 2025.07 shim of the io_encoding plugin (pymeshlab 2025.7): IOPlugin over contour_io.h
// and the shared host adapter. A failure becomes MLException, which pymeshlab raises as
// PyMeshLabException with the message.
#include "host_meshlab_2025.h"
// (the traits header first: host_adapter.h needs the MeshLab declarations)
#include <common/plugins/interfaces/io_plugin.h>

#include "contour_io.h"
#include "host_adapter.h"

namespace slicereuse::plugin {

// ::FileFormat is MeshLab's (extension + description), not slicereuse::FileFormat.

class IoEncodingPlugin : public QObject, public IOPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(IO_PLUGIN_IID)
  Q_INTERFACES(IOPlugin)

 public:
  QString pluginName() const override { return "IOEncoding"; }
  QString vendor() const override { return "slicereuse"; }

  std::list<::FileFormat> importFormats() const override { return formats(true); }
  std::list<::FileFormat> exportFormats() const override { return formats(false); }

  void exportMaskCapability(const QString&, int& capability, int& defaultBits) const override {
    capability = defaultBits = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_EDGEINDEX;
  }

  RichParameterList initSaveParameter(const QString& format, const MeshModel&) const override {
    RichParameterList par;
    if (upper(format.toStdString()) == "CLI")
      par.addParam(RichBool(kCliBinaryParameter, false, "Binary CLI",
                            "Write binary CLI (float32 coordinates) instead of ASCII (exact decimals)."));
    return par;
  }

  void open(const QString& format, const QString& fileName, MeshModel& m, int& mask,
            const RichParameterList&, vcg::CallBackPos* cb) override {
    std::string line;
    if (const auto failure = failure_of("Open " + fileName.toStdString(), [&] {
          line = open_contour_file(format.toStdString(), fileName.toStdString(), m.cm, progress_of(cb));
        }))
      throw MLException(to_qstring(*failure));
    mask = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_EDGEINDEX;
    log(line);
  }

  void save(const QString& format, const QString& fileName, MeshModel& m, const int,
            const RichParameterList& par, vcg::CallBackPos* cb) override {
    const bool binary = par.hasParameter(kCliBinaryParameter) && par.getBool(kCliBinaryParameter);
    std::string line;
    if (const auto failure = failure_of("Save " + fileName.toStdString(), [&] {
          line = save_contour_layer(format.toStdString(), fileName.toStdString(), m.cm, binary, progress_of(cb));
        }))
      throw MLException(to_qstring(*failure));
    log(line);
  }

 private:
  static std::list<::FileFormat> formats(bool opening) {
    std::list<::FileFormat> list;
    for (const IoFormat& f : io_formats())
      if (f.opens || !opening) list.emplace_back(f.description, f.extension);
    return list;
  }
};

}  // namespace slicereuse::plugin

#include "shim_2025.moc"
