#pragma once

#include <QObject>
#include <QStringList>

class QAction;
class QProcess;
class QWidget;

namespace rosarch {

class Document;
class LogView;

/// File › Export and Render with PlantUML: writes the artifacts (as Export Artifacts does)
/// and renders every ACD and CCD to SVG with the real PlantUML, in the background (a Java
/// process; the window stays responsive and a new render or closing stops the old one).
/// File › PlantUML Jar… sets which jar; without one, or without Java, a dialog says how to
/// get it.
class RenderController : public QObject
{
    Q_OBJECT
public:
    RenderController(Document *document, LogView *log, QWidget *window);
    ~RenderController() override;

    QAction *renderAction() const { return m_renderAction; }
    QAction *jarAction() const { return m_jarAction; }

    /// Exports to `folder` and starts rendering; false (with a message shown) when the
    /// artifacts cannot be written or no renderer is found.
    bool exportAndRender(const QString &folder);
    bool isRendering() const;

Q_SIGNALS:
    /// Rendering ended: `ok`, or failed with PlantUML's `message`.
    void rendered(bool ok, const QString &message, const QStringList &pictures);
    /// A line for the status bar.
    void status(const QString &message);

private:
    void chooseFolder();
    bool chooseJar();
    void showError(const QString &title, const QString &text);

    Document *m_document;
    LogView *m_log;
    QWidget *m_window;
    QAction *m_renderAction;
    QAction *m_jarAction;
    QProcess *m_process = nullptr;
    QStringList m_pictures;
};

} // namespace rosarch
