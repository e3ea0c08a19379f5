#pragma once

#include <QDialog>

namespace rosarch {

/// Help → About: what rosarch is and the versions of the libraries it was built with.
class AboutDialog : public QDialog
{
    Q_OBJECT
public:
    explicit AboutDialog(QWidget *parent = nullptr);

    /// The version lines shown, for tests and bug reports.
    static QString versionsHtml();
};

} // namespace rosarch
