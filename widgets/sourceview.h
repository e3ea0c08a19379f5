#pragma once

#include "core/evidence.h"

#include <QHash>
#include <QWidget>

class QLabel;
class QsciLexer;
class QsciScintilla;

namespace rosarch {

/// The "Source" panel: a read-only editor showing the file an element comes from, with its
/// evidence range highlighted. Tells the window when a person moves the cursor to a line.
class SourceView : public QWidget
{
    Q_OBJECT
public:
    explicit SourceView(QWidget *parent = nullptr);
    ~SourceView() override;

    /// Evidence paths are relative to this folder.
    void setWorkspaceRoot(const QString &root);
    QString workspaceRoot() const { return m_root; }

    /// Opens the evidence file (if not already shown), highlights the range and moves the
    /// cursor to its start. Returns false (and says why in the header) when it cannot.
    bool showEvidence(const Evidence &evidence);
    void clear();
    /// Puts the cursor on `line` and shows from `firstLine` (0-based), as showEvidence moves
    /// it: not reported as a person's move.
    void setPosition(int line, int firstLine);

    QString currentFile() const { return m_file; }         ///< relative to the workspace root
    Evidence highlighted() const { return m_highlighted; } ///< invalid when nothing is
    QsciScintilla *editor() const { return m_editor; }
    /// Marker bit set on the first line of the highlighted range.
    int evidenceMarker() const { return m_arrowMarker; }
    /// Indicator number of the highlighted range.
    int evidenceIndicator() const { return kEvidenceIndicator; }
    /// True when the person's last move in the editor was a key (reading with the arrow keys),
    /// false after a click: what a move may interrupt with a question.
    bool movedByKey() const { return m_movedByKey; }

Q_SIGNALS:
    /// A person moved the cursor to `line` (1-based) of `file`; not sent for moves made by
    /// showEvidence, so following a selection does not echo back.
    void cursorLineChanged(const QString &file, int line);

protected:
    void changeEvent(QEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    static constexpr int kEvidenceIndicator = 8;

    bool loadFile(const QString &file);
    void highlight(const Evidence &evidence);
    void clearHighlight();
    int bytePosition(int line, int column) const;
    QsciLexer *lexerFor(const QString &file);
    void applyPalette();
    void styleLexer(QsciLexer *lexer);
    void updateHeader();
    void onCursorPositionChanged(int line, int index);

    QString m_root;
    QString m_file;
    Evidence m_highlighted;
    QString m_headerProblem;
    QLabel *m_pathLabel;
    QLabel *m_lineLabel;
    QsciScintilla *m_editor;
    QHash<QString, QsciLexer *> m_lexers; ///< by language key, owned by this widget
    int m_arrowMarker = 0;
    int m_rangeMarker = 1;
    bool m_navigating = false; ///< set while showEvidence moves the cursor
    /// QScintilla reports cursor moves later (on its UI update), so the line showEvidence moved
    /// to is remembered and its report swallowed; -1 when no such report is pending.
    int m_pendingProgrammaticLine = -1;
    int m_lastReportedLine = -1;
    bool m_movedByKey = false;
};

} // namespace rosarch
