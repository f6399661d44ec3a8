// MeshLab 2020.09 shim of the io_encoding plugin: MeshIOInterface over contour_io.h and the
// shared host adapter (progress, error messages, logging). A failure returns false with
// errorMessage set and logged (meshlabserver prints only the log); nothing reaches an assertion.
#include "host_meshlab_2020.h"
// (the traits header first: host_adapter.h needs the MeshLab declarations)
#include "contour_io.h"
#include "host_adapter.h"

using namespace slicereuse::plugin;

class IoEncodingPlugin : public QObject, public MeshIOInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_IO_INTERFACE_IID)
  Q_INTERFACES(MeshIOInterface)

 public:
  QString pluginName() const override { return "IOEncoding"; }

  QList<Format> importFormats() const override { return formats(true); }
  QList<Format> exportFormats() const override { return formats(false); }

  void GetExportMaskCapability(QString&, int& capability, int& defaultBits) const override {
    capability = defaultBits = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_EDGEINDEX;
  }

  void initSaveParameter(const QString& format, MeshModel&, RichParameterList& par) override {
    if (upper(format.toStdString()) == "CLI")
      par.addParam(RichBool(kCliBinaryParameter, false, "Binary CLI",
                            "Write binary CLI (float32 coordinates) instead of ASCII (exact decimals)."));
  }

  bool open(const QString& format, const QString& fileName, MeshModel& m, int& mask,
            const RichParameterList&, vcg::CallBackPos* cb, QWidget*) override {
    std::string line;
    const auto failure = failure_of("Open " + fileName.toStdString(), [&] {
      line = open_contour_file(format.toStdString(), fileName.toStdString(), m.cm, progress_of(cb));
    });
    if (failure) return fail(*failure);
    mask = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_EDGEINDEX;
    Log(line);
    return true;
  }

  bool save(const QString& format, const QString& fileName, MeshModel& m, const int,
            const RichParameterList& par, vcg::CallBackPos* cb, QWidget*) override {
    const bool binary = par.hasParameter(kCliBinaryParameter) && par.getBool(kCliBinaryParameter);
    std::string line;
    const auto failure = failure_of("Save " + fileName.toStdString(), [&] {
      line = save_contour_layer(format.toStdString(), fileName.toStdString(), m.cm, binary, progress_of(cb));
    });
    if (failure) return fail(*failure);
    Log(line);
    return true;
  }

 private:
  static QList<Format> formats(bool opening) {
    QList<Format> list;
    for (const IoFormat& f : io_formats())
      if (f.opens || !opening) list << Format(f.description, f.extension);
    return list;
  }
  bool fail(const std::string& message) {
    errorMessage = to_qstring(message);
    Log(GLLogStream::WARNING, "Error: " + message);
    return false;
  }
};

#include "shim_2020.moc"
