#include "widgets/sourceview.h"

#include <Qsci/qscilexercmake.h>
#include <Qsci/qscilexercpp.h>
#include <Qsci/qscilexerpython.h>
#include <Qsci/qscilexerxml.h>
#include <Qsci/qscilexeryaml.h>
#include <Qsci/qsciscintilla.h>

#include <QDir>
#include <QEvent>
#include <QFile>
#include <QFileInfo>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>

namespace rosarch {

namespace {

constexpr qint64 kMaxFileBytes = 8 * 1024 * 1024;

QString languageKey(const QString &file)
{
    const QFileInfo info(file);
    const QString suffix = info.suffix().toLower();
    const QString name = info.fileName().toLower();
    if (suffix == QLatin1String("py"))
        return QStringLiteral("python");
    static const QStringList cpp{
        QStringLiteral("cpp"), QStringLiteral("hpp"), QStringLiteral("h"),
        QStringLiteral("cc"),  QStringLiteral("cxx"), QStringLiteral("hh"),
        QStringLiteral("hxx"), QStringLiteral("c"),   QStringLiteral("ipp")};
    if (cpp.contains(suffix))
        return QStringLiteral("cpp");
    if (name == QLatin1String("cmakelists.txt") || suffix == QLatin1String("cmake"))
        return QStringLiteral("cmake");
    static const QStringList xml{QStringLiteral("xml"), QStringLiteral("launch"),
                                 QStringLiteral("urdf"), QStringLiteral("xacro"),
                                 QStringLiteral("sdf")};
    if (xml.contains(suffix))
        return QStringLiteral("xml");
    if (suffix == QLatin1String("yaml") || suffix == QLatin1String("yml"))
        return QStringLiteral("yaml");
    return {};
}

QColor mix(const QColor &a, const QColor &b, qreal t)
{
    return QColor::fromRgbF(a.redF() * (1 - t) + b.redF() * t,
                            a.greenF() * (1 - t) + b.greenF() * t,
                            a.blueF() * (1 - t) + b.blueF() * t);
}

/// Lexer colours are chosen for white paper; on dark paper keep the hue, flip the lightness.
QColor readable(const QColor &c, bool dark)
{
    if (!dark)
        return c;
    const float l = std::clamp(1.0f - c.lightnessF(), 0.62f, 0.9f);
    return QColor::fromHslF(c.hslHueF() < 0 ? 0 : c.hslHueF(), std::min(c.hslSaturationF(), 0.75f),
                            l);
}

} // namespace

SourceView::SourceView(QWidget *parent)
    : QWidget(parent), m_pathLabel(new QLabel(this)), m_lineLabel(new QLabel(this)),
      m_editor(new QsciScintilla(this))
{
    m_pathLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_pathLabel->setMinimumWidth(40); // long paths are cut, the line label stays whole
    m_lineLabel->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_lineLabel->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Preferred);
    auto *header = new QHBoxLayout;
    header->setContentsMargins(6, 3, 6, 3);
    header->addWidget(m_pathLabel, 1);
    header->addWidget(m_lineLabel);

    m_editor->setReadOnly(true);
    m_editor->setUtf8(true);
    m_editor->setCaretLineVisible(true);
    m_editor->setWrapMode(QsciScintilla::WrapNone);
    // Horizontal scroll bar only as wide as the longest line seen, not a fixed 2000 px.
    m_editor->SendScintilla(QsciScintilla::SCI_SETSCROLLWIDTH, 1);
    m_editor->SendScintilla(QsciScintilla::SCI_SETSCROLLWIDTHTRACKING, true);
    m_editor->setFrameShape(QFrame::NoFrame);
    m_editor->setMarginType(0, QsciScintilla::NumberMargin);
    m_editor->setMarginLineNumbers(0, true);
    m_editor->setMarginType(1, QsciScintilla::SymbolMargin);
    m_editor->setMarginWidth(1, 14);
    m_editor->setMarginSensitivity(1, false);
    m_arrowMarker = m_editor->markerDefine(QsciScintilla::RightTriangle, 0);
    m_rangeMarker = m_editor->markerDefine(QsciScintilla::LeftRectangle, 1);
    m_editor->setMarginMarkerMask(1, (1 << m_arrowMarker) | (1 << m_rangeMarker));
    m_editor->SendScintilla(QsciScintilla::SCI_INDICSETSTYLE, kEvidenceIndicator,
                            QsciScintilla::INDIC_STRAIGHTBOX);
    m_editor->SendScintilla(QsciScintilla::SCI_INDICSETUNDER, kEvidenceIndicator, true);
    m_editor->SendScintilla(QsciScintilla::SCI_INDICSETALPHA, kEvidenceIndicator, 70);
    m_editor->SendScintilla(QsciScintilla::SCI_INDICSETOUTLINEALPHA, kEvidenceIndicator, 160);
    connect(m_editor, &QsciScintilla::cursorPositionChanged, this,
            &SourceView::onCursorPositionChanged);
    m_editor->installEventFilter(this);
    m_editor->viewport()->installEventFilter(this);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addLayout(header);
    layout->addWidget(m_editor, 1);
    setFocusProxy(m_editor);

    applyPalette();
    updateHeader();
}

SourceView::~SourceView()
{
    m_editor->setLexer(nullptr);
    qDeleteAll(m_lexers);
}

void SourceView::setWorkspaceRoot(const QString &root)
{
    if (root == m_root)
        return;
    m_root = root;
    clear();
}

void SourceView::clear()
{
    m_file.clear();
    m_highlighted = {};
    m_headerProblem.clear();
    m_editor->setLexer(nullptr);
    m_editor->clear();
    m_editor->setMarginWidth(0, 0); // an empty page without a gutter
    m_editor->setMarginWidth(1, 0);
    applyPalette();
    updateHeader();
}

bool SourceView::showEvidence(const Evidence &evidence)
{
    if (evidence.file.isEmpty())
        return false;
    if (evidence.file != m_file && !loadFile(evidence.file))
        return false;
    highlight(evidence);
    updateHeader();
    return true;
}

bool SourceView::loadFile(const QString &file)
{
    const QString path = QDir(m_root).filePath(file);
    QFile f(path);
    QString problem;
    if (!f.open(QIODevice::ReadOnly))
        problem = tr("Cannot open %1: %2").arg(file, f.errorString());
    else if (f.size() > kMaxFileBytes)
        problem = tr("%1 is too large to show (%2 MB)").arg(file).arg(f.size() / (1024 * 1024));
    if (!problem.isEmpty()) {
        clear();
        m_headerProblem = problem;
        updateHeader();
        return false;
    }
    const QByteArray content = f.readAll();
    m_navigating = true;
    m_editor->setLexer(lexerFor(file));
    m_editor->setText(QString::fromUtf8(content));
    m_navigating = false;
    m_file = file;
    m_highlighted = {};
    m_headerProblem.clear();
    applyPalette();
    const int digits = QString::number(std::max(1, m_editor->lines())).size();
    m_editor->setMarginWidth(0, QString(digits + 1, QLatin1Char('9')));
    m_editor->setMarginWidth(1, 14);
    return true;
}

int SourceView::bytePosition(int line, int column) const
{
    // Evidence columns count UTF-8 bytes, like Scintilla positions in UTF-8 mode.
    const int zeroLine = std::clamp(line - 1, 0, std::max(0, m_editor->lines() - 1));
    const long start = m_editor->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, zeroLine);
    const long end = m_editor->SendScintilla(QsciScintilla::SCI_GETLINEENDPOSITION, zeroLine);
    if (column <= 0)
        return int(start);
    return int(std::min(start + column - 1, end));
}

void SourceView::clearHighlight()
{
    m_editor->markerDeleteAll(m_arrowMarker);
    m_editor->markerDeleteAll(m_rangeMarker);
    m_editor->SendScintilla(QsciScintilla::SCI_SETINDICATORCURRENT, kEvidenceIndicator);
    m_editor->SendScintilla(QsciScintilla::SCI_INDICATORCLEARRANGE, 0,
                            m_editor->SendScintilla(QsciScintilla::SCI_GETLENGTH));
    m_highlighted = {};
}

void SourceView::highlight(const Evidence &evidence)
{
    clearHighlight();
    const int firstLine = std::clamp(evidence.line, 1, std::max(1, m_editor->lines()));
    const int lastLine = std::clamp(std::max(evidence.endLine, firstLine), firstLine,
                                    std::max(1, m_editor->lines()));
    const int start = bytePosition(firstLine, evidence.column);
    int end = evidence.endLine >= firstLine && evidence.endColumn > 0
                  ? bytePosition(lastLine, evidence.endColumn)
                  : bytePosition(lastLine, 1 << 30);
    if (end <= start) // an empty or unknown range: mark the whole first line
        end = bytePosition(firstLine, 1 << 30);
    m_editor->SendScintilla(QsciScintilla::SCI_SETINDICATORCURRENT, kEvidenceIndicator);
    m_editor->SendScintilla(QsciScintilla::SCI_INDICATORFILLRANGE, start, end - start);
    for (int l = firstLine; l <= lastLine; ++l)
        m_editor->markerAdd(l - 1, m_rangeMarker);
    m_editor->markerAdd(firstLine - 1, m_arrowMarker);
    m_highlighted = evidence;

    m_navigating = true;
    int cursorLine = 0;
    int cursorIndex = 0;
    m_editor->lineIndexFromPosition(start, &cursorLine, &cursorIndex);
    m_editor->setCursorPosition(cursorLine, cursorIndex);
    const int visible = std::max(1, int(m_editor->SendScintilla(QsciScintilla::SCI_LINESONSCREEN)));
    m_editor->setFirstVisibleLine(std::max(0, firstLine - 1 - visible / 3));
    m_navigating = false;
    m_pendingProgrammaticLine = cursorLine;
    m_lastReportedLine = -1;
}

void SourceView::setPosition(int line, int firstLine)
{
    m_navigating = true;
    m_editor->setCursorPosition(line, 0);
    m_editor->setFirstVisibleLine(firstLine);
    m_navigating = false;
    m_pendingProgrammaticLine = line;
    m_lastReportedLine = -1;
}

void SourceView::onCursorPositionChanged(int line, int)
{
    if (m_navigating || m_file.isEmpty())
        return;
    if (line == m_pendingProgrammaticLine) {
        m_pendingProgrammaticLine = -1;
        m_lastReportedLine = line;
        return;
    }
    m_pendingProgrammaticLine = -1;
    if (line == m_lastReportedLine)
        return;
    m_lastReportedLine = line;
    Q_EMIT cursorLineChanged(m_file, line + 1);
}

QsciLexer *SourceView::lexerFor(const QString &file)
{
    const QString key = languageKey(file);
    if (key.isEmpty())
        return nullptr;
    if (QsciLexer *lexer = m_lexers.value(key))
        return lexer;
    QsciLexer *lexer = nullptr;
    if (key == QLatin1String("python"))
        lexer = new QsciLexerPython;
    else if (key == QLatin1String("cpp"))
        lexer = new QsciLexerCPP;
    else if (key == QLatin1String("cmake"))
        lexer = new QsciLexerCMake;
    else if (key == QLatin1String("yaml"))
        lexer = new QsciLexerYAML;
    else
        lexer = new QsciLexerXML;
    m_lexers.insert(key, lexer);
    styleLexer(lexer);
    return lexer;
}

void SourceView::styleLexer(QsciLexer *lexer)
{
    const QPalette pal = palette();
    const QColor paper = pal.color(QPalette::Base);
    const QColor text = pal.color(QPalette::Text);
    const bool dark = paper.lightnessF() < 0.5;
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    lexer->setDefaultPaper(paper);
    lexer->setDefaultColor(text);
    lexer->setDefaultFont(mono);
    for (int style = 0; style < 128; ++style) {
        if (lexer->description(style).isEmpty())
            continue;
        QFont f = mono;
        f.setBold(lexer->defaultFont(style).bold());
        f.setItalic(lexer->defaultFont(style).italic());
        lexer->setFont(f, style);
        lexer->setPaper(paper, style);
        const QColor c = lexer->defaultColor(style);
        lexer->setColor(c == Qt::black ? text : readable(c, dark), style);
    }
}

void SourceView::applyPalette()
{
    const QPalette pal = palette();
    const QColor paper = pal.color(QPalette::Base);
    const QColor text = pal.color(QPalette::Text);
    const QColor highlight = pal.color(QPalette::Highlight);
    for (QsciLexer *lexer : std::as_const(m_lexers))
        styleLexer(lexer);
    if (!m_editor->lexer()) {
        m_editor->setPaper(paper);
        m_editor->setColor(text);
        m_editor->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    }
    m_editor->setMarginsBackgroundColor(mix(paper, pal.color(QPalette::Window), 0.7));
    m_editor->setMarginsForegroundColor(mix(text, paper, 0.5));
    m_editor->setMarginsFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_editor->setCaretForegroundColor(text);
    m_editor->setCaretLineBackgroundColor(mix(paper, text, 0.06));
    m_editor->setSelectionBackgroundColor(highlight);
    m_editor->setSelectionForegroundColor(pal.color(QPalette::HighlightedText));
    m_editor->setMarkerBackgroundColor(highlight, m_arrowMarker);
    m_editor->setMarkerForegroundColor(highlight, m_arrowMarker);
    m_editor->setMarkerBackgroundColor(mix(highlight, paper, 0.35), m_rangeMarker);
    m_editor->setMarkerForegroundColor(mix(highlight, paper, 0.35), m_rangeMarker);
    const QColor indicator = paper.lightnessF() < 0.5 ? highlight.lighter(130) : highlight;
    m_editor->SendScintilla(QsciScintilla::SCI_INDICSETFORE, kEvidenceIndicator, indicator);

    m_pathLabel->setPalette(pal);
    m_lineLabel->setForegroundRole(QPalette::PlaceholderText);
}

void SourceView::updateHeader()
{
    // A sentence wraps in a narrow pane (1024 px wide windows); a path is cut instead.
    m_pathLabel->setWordWrap(!m_headerProblem.isEmpty() || m_file.isEmpty());
    if (!m_headerProblem.isEmpty()) {
        m_pathLabel->setText(m_headerProblem);
        m_pathLabel->setToolTip(m_headerProblem);
        m_lineLabel->clear();
        return;
    }
    if (m_file.isEmpty()) {
        m_pathLabel->setText(
            tr("Select a node, port, launch item or diagnostic to see its source."));
        m_pathLabel->setToolTip(QString());
        m_lineLabel->clear();
        return;
    }
    m_pathLabel->setText(QStringLiteral("<b>%1</b>").arg(m_file.toHtmlEscaped()));
    m_pathLabel->setToolTip(QDir::toNativeSeparators(QDir(m_root).filePath(m_file)));
    if (!m_highlighted.isValid())
        m_lineLabel->clear();
    else if (m_highlighted.endLine > m_highlighted.line)
        m_lineLabel->setText(tr("lines %1–%2").arg(m_highlighted.line).arg(m_highlighted.endLine));
    else
        m_lineLabel->setText(tr("line %1").arg(m_highlighted.line));
}

bool SourceView::eventFilter(QObject *watched, QEvent *event)
{
    // A person acting on the editor: whatever move follows is theirs, even to the same line.
    if (event->type() == QEvent::MouseButtonPress || event->type() == QEvent::KeyPress) {
        m_pendingProgrammaticLine = -1;
        m_lastReportedLine = -1;
        m_movedByKey = event->type() == QEvent::KeyPress;
    }
    return QWidget::eventFilter(watched, event);
}

void SourceView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::PaletteChange)
        applyPalette();
    QWidget::changeEvent(event);
}

} // namespace rosarch
