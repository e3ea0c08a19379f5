#include "workspace/buildfileparser.h"
#include "syntax/syntaxtree.h"

#include <QHash>
#include <QRegularExpression>
#include <QXmlStreamReader>

namespace rosarch {

namespace {

Evidence lineEvidence(const QString &file, int line)
{
    Evidence e;
    e.file = file;
    e.line = line;
    e.column = 1;
    e.endLine = line;
    e.endColumn = 1;
    return e;
}

// "talker = demo_nodes_py.topics.talker:main" -> executable
bool parseEntryPoint(const QString &spec, Executable *exe)
{
    static const QRegularExpression re(
        QStringLiteral("^\\s*([^=\\s]+)\\s*=\\s*([A-Za-z0-9_.]+)\\s*(?::\\s*([A-Za-z0-9_.]+))?"));
    const auto m = re.match(spec);
    if (!m.hasMatch())
        return false;
    exe->kind = Executable::Kind::ConsoleScript;
    exe->name = m.captured(1);
    exe->target = m.captured(2) + QLatin1Char(':') +
                  (m.captured(3).isEmpty() ? QStringLiteral("main") : m.captured(3));
    return true;
}

/// Evaluates the small string expressions setup.py files use for entry points.
class SetupPyEvaluator
{
public:
    explicit SetupPyEvaluator(const SyntaxTree &tree) : m_tree(tree) {}

    void collectStringVariables(TSNode root)
    {
        for (TSNode stmt : ts::namedChildren(root)) {
            if (!ts::is(stmt, "expression_statement"))
                continue;
            TSNode assign = ts_node_named_child(stmt, 0);
            if (!ts::is(assign, "assignment"))
                continue;
            TSNode left = ts::field(assign, "left");
            TSNode right = ts::field(assign, "right");
            if (!ts::is(left, "identifier"))
                continue;
            bool ok = false;
            const QString value = evaluate(right, &ok);
            if (ok)
                m_vars.insert(m_tree.text(left), value);
        }
    }

    /// Deeper than this, an expression is not evaluated (a generated or hostile setup.py
    /// must not overflow the stack); entry points nest two or three levels.
    static constexpr int kMaxDepth = 100;

    QString evaluate(TSNode n, bool *ok, int depth = 0) const
    {
        *ok = true;
        if (depth > kMaxDepth) {
            *ok = false;
            return {};
        }
        const auto t = ts::type(n);
        if (t == "string") {
            QString out;
            for (TSNode c : ts::namedChildren(n)) {
                if (ts::is(c, "string_content"))
                    out += m_tree.text(c);
                else if (ts::is(c, "interpolation")) {
                    bool inner = false;
                    out += evaluate(ts::field(c, "expression"), &inner, depth + 1);
                    *ok = *ok && inner;
                }
            }
            return out;
        }
        if (t == "concatenated_string") {
            QString out;
            for (TSNode c : ts::namedChildren(n)) {
                bool inner = false;
                out += evaluate(c, &inner, depth + 1);
                *ok = *ok && inner;
            }
            return out;
        }
        if (t == "binary_operator") {
            bool a = false, b = false;
            const QString s = evaluate(ts::field(n, "left"), &a, depth + 1) +
                              evaluate(ts::field(n, "right"), &b, depth + 1);
            *ok = a && b;
            return s;
        }
        if (t == "identifier" && m_vars.contains(m_tree.text(n)))
            return m_vars.value(m_tree.text(n));
        if (t == "parenthesized_expression")
            return evaluate(ts_node_named_child(n, 0), ok, depth + 1);
        *ok = false;
        return {};
    }

private:
    const SyntaxTree &m_tree;
    QHash<QString, QString> m_vars;
};

} // namespace

void BuildFileParser::readPackageXml(const QByteArray &content, const QString &file,
                                     RosPackage *package, QList<Diagnostic> *diagnostics)
{
    QXmlStreamReader xml(content);
    QStringList path;
    while (!xml.atEnd()) {
        const auto token = xml.readNext();
        if (token == QXmlStreamReader::StartElement) {
            path.append(xml.name().toString());
            // Only package/name, package/version and package/export/build_type are read: deeper
            // elements are not joined (a deeply nested file would make this quadratic).
            const QString joined = path.size() <= 3 ? path.join(QLatin1Char('/')) : QString();
            if (joined == QLatin1String("package/name")) {
                const int line = int(xml.lineNumber());
                package->name = xml.readElementText().trimmed();
                package->evidence = lineEvidence(file, line);
                path.removeLast();
            } else if (joined == QLatin1String("package/version")) {
                package->version = xml.readElementText().trimmed();
                path.removeLast();
            } else if (joined == QLatin1String("package/export/build_type")) {
                package->buildType = xml.readElementText().trimmed();
                path.removeLast();
            }
        } else if (token == QXmlStreamReader::EndElement) {
            if (!path.isEmpty())
                path.removeLast();
        }
    }
    if (xml.hasError()) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Error;
        d.code = QStringLiteral("malformed-xml");
        d.message = QStringLiteral("%1 is not well-formed XML (line %2: %3).")
                        .arg(file)
                        .arg(xml.lineNumber())
                        .arg(xml.errorString());
        d.evidence = lineEvidence(file, int(xml.lineNumber()));
        diagnostics->append(d);
    }
    if (package->buildType.isEmpty())
        package->buildType = QStringLiteral("ament_cmake"); // REP 149 default
}

QList<Executable> BuildFileParser::readSetupPy(const QByteArray &content, const QString &file,
                                               QList<Diagnostic> *diagnostics)
{
    QList<Executable> out;
    const SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Python, content, file);
    diagnostics->append(tree.syntaxErrors(1));
    SetupPyEvaluator eval(tree);
    eval.collectStringVariables(tree.root());
    // Every string inside a list that follows a 'console_scripts' key or keyword.
    ts::walk(tree.root(), [&](TSNode n) {
        if (!ts::is(n, "pair") && !ts::is(n, "keyword_argument"))
            return true;
        TSNode key = ts::is(n, "pair") ? ts::field(n, "key") : ts::field(n, "name");
        bool ok = false;
        const QString keyText =
            ts::is(key, "identifier") ? tree.text(key) : eval.evaluate(key, &ok);
        if (keyText != QLatin1String("console_scripts"))
            return true;
        TSNode value = ts::field(n, "value");
        for (TSNode item : ts::namedChildren(value)) {
            bool itemOk = false;
            const QString spec = eval.evaluate(item, &itemOk);
            Executable exe;
            if (itemOk && parseEntryPoint(spec, &exe)) {
                exe.evidence = tree.evidence(item);
                out.append(exe);
            } else {
                Diagnostic d;
                d.severity = Diagnostic::Severity::Info;
                d.code = QStringLiteral("unresolved-entry-point");
                d.message =
                    QStringLiteral("console_scripts entry %1 could not be evaluated statically.")
                        .arg(tree.text(item));
                d.evidence = tree.evidence(item);
                diagnostics->append(d);
            }
        }
        return false;
    });
    return out;
}

QList<Executable> BuildFileParser::readSetupCfg(const QByteArray &content, const QString &file)
{
    QList<Executable> out;
    const QStringList lines = QString::fromUtf8(content).split(QLatin1Char('\n'));
    QString section;
    bool inScripts = false;
    for (int i = 0; i < lines.size(); ++i) {
        const QString &raw = lines[i];
        const QString line = raw.trimmed();
        if (line.startsWith(QLatin1Char('[')) && line.endsWith(QLatin1Char(']'))) {
            section = line.mid(1, line.size() - 2).trimmed();
            inScripts = false;
            continue;
        }
        if (section != QLatin1String("options.entry_points") || line.isEmpty() ||
            line.startsWith(QLatin1Char('#')) || line.startsWith(QLatin1Char(';')))
            continue;
        const bool indented = raw.startsWith(QLatin1Char(' ')) || raw.startsWith(QLatin1Char('\t'));
        if (!indented) {
            const qsizetype eq = line.indexOf(QLatin1Char('='));
            inScripts = eq > 0 && line.left(eq).trimmed() == QLatin1String("console_scripts");
            const QString rest = eq > 0 ? line.mid(eq + 1).trimmed() : QString();
            Executable exe;
            if (inScripts && !rest.isEmpty() && parseEntryPoint(rest, &exe)) {
                exe.evidence = lineEvidence(file, i + 1);
                out.append(exe);
            }
            continue;
        }
        Executable exe;
        if (inScripts && parseEntryPoint(line, &exe)) {
            exe.evidence = lineEvidence(file, i + 1);
            out.append(exe);
        }
    }
    return out;
}

} // namespace rosarch
