#include "workspace/cmakelistsreader.h"

#include "core/valuebudget.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

#include <optional>

namespace rosarch {

namespace {
constexpr int kMaxSubdirectoryDepth = 8;

/// A note that the reader did not follow something (too deep, too many, already read).
void notFollowed(const QString &message, const Evidence &where, QList<Diagnostic> *diagnostics)
{
    Diagnostic d;
    d.code = QStringLiteral("cmake-depth");
    d.message = message;
    d.evidence = where;
    diagnostics->append(d);
}

/// The commands of the block (function, macro, foreach) opened at `*index`, up to the `end...`
/// that closes it, blocks of the same kind nested inside counted; `*index` ends on that `end`.
QList<CMakeListsReader::Command> blockBody(const QList<CMakeListsReader::Command> &commands,
                                           qsizetype *index)
{
    const QString open = commands[*index].name;
    const QString end = QStringLiteral("end") + open;
    QList<CMakeListsReader::Command> body;
    int nesting = 0;
    for (++*index; *index < commands.size(); ++*index) {
        if (commands[*index].name == open)
            ++nesting;
        if (commands[*index].name == end && nesting-- == 0)
            break;
        body.append(commands[*index]);
    }
    return body;
}

QString joinPath(const QString &dir, const QString &path)
{
    if (dir.isEmpty())
        return QDir::cleanPath(path);
    return QDir::cleanPath(dir + QLatin1Char('/') + path);
}

bool isSourceFile(const QString &s)
{
    static const QRegularExpression re(QStringLiteral("\\.(c|cc|cpp|cxx|h|hh|hpp|hxx)$"));
    return re.match(s).hasMatch();
}
} // namespace

CMakeListsReader::CMakeListsReader(Loader load) : m_load(std::move(load)) {}

QList<CMakeListsReader::Command> CMakeListsReader::tokenize(const QByteArray &content)
{
    QList<Command> out;
    const QString text = QString::fromUtf8(content);
    const qsizetype n = text.size();
    qsizetype i = 0;
    int line = 1;
    auto skipComment = [&]() {
        // Bracket comments #[[ ... ]] and line comments.
        if (text.mid(i, 3) == QLatin1String("#[[")) {
            const qsizetype end = text.indexOf(QLatin1String("]]"), i + 3);
            const qsizetype stop = end < 0 ? n : end + 2;
            line += int(text.mid(i, stop - i).count(QLatin1Char('\n')));
            i = stop;
            return;
        }
        while (i < n && text[i] != QLatin1Char('\n'))
            ++i;
    };
    while (i < n) {
        const QChar c = text[i];
        if (c == QLatin1Char('\n')) {
            ++line;
            ++i;
        } else if (c.isSpace()) {
            ++i;
        } else if (c == QLatin1Char('#')) {
            skipComment();
        } else if (c.isLetter() || c == QLatin1Char('_')) {
            qsizetype j = i;
            while (j < n && (text[j].isLetterOrNumber() || text[j] == QLatin1Char('_')))
                ++j;
            Command cmd;
            cmd.name = text.mid(i, j - i).toLower();
            cmd.line = line;
            i = j;
            while (i < n && (text[i] == QLatin1Char(' ') || text[i] == QLatin1Char('\t')))
                ++i;
            if (i >= n || text[i] != QLatin1Char('(')) {
                continue; // not a command invocation; resynchronise
            }
            ++i;
            int depth = 1;
            QString current;
            bool hasCurrent = false;
            auto flush = [&]() {
                if (hasCurrent)
                    cmd.args.append(current);
                current.clear();
                hasCurrent = false;
            };
            while (i < n && depth > 0) {
                const QChar d = text[i];
                if (d == QLatin1Char('"')) {
                    ++i;
                    hasCurrent = true;
                    while (i < n && text[i] != QLatin1Char('"')) {
                        if (text[i] == QLatin1Char('\\') && i + 1 < n) {
                            current += text[i + 1];
                            i += 2;
                            continue;
                        }
                        if (text[i] == QLatin1Char('\n'))
                            ++line;
                        current += text[i++];
                    }
                    ++i;
                } else if (d == QLatin1Char('#')) {
                    flush();
                    skipComment();
                } else if (d == QLatin1Char('(')) {
                    ++depth;
                    flush();
                    ++i;
                } else if (d == QLatin1Char(')')) {
                    --depth;
                    flush();
                    ++i;
                } else if (d.isSpace()) {
                    if (d == QLatin1Char('\n'))
                        ++line;
                    flush();
                    ++i;
                } else {
                    current += d;
                    hasCurrent = true;
                    ++i;
                }
            }
            cmd.endLine = line;
            out.append(cmd);
        } else {
            ++i;
        }
    }
    return out;
}

bool CMakeListsReader::takeBodyRun(const Evidence &where, QList<Diagnostic> *diagnostics)
{
    if (m_bodyRuns++ < kMaxBodyRuns)
        return true;
    if (m_bodyRuns == kMaxBodyRuns + 1) {
        notFollowed(QStringLiteral("%1 runs more than %2 function calls and loop iterations; "
                                   "the rest were not followed.")
                        .arg(where.file)
                        .arg(kMaxBodyRuns),
                    where, diagnostics);
    }
    return false;
}

QStringList CMakeListsReader::foreachItems(const QStringList &rawArgs) const
{
    if (rawArgs.value(0) == QLatin1String("RANGE")) {
        // RANGE stop | start stop [step], inclusive.
        const QStringList n = expandArgs(rawArgs.mid(1));
        bool ok[3] = {true, true, true};
        const int start = n.size() >= 2 ? n[0].toInt(&ok[0]) : 0;
        const int stop = n.value(n.size() >= 2 ? 1 : 0).toInt(&ok[1]);
        const int step = n.size() >= 3 ? n[2].toInt(&ok[2]) : 1;
        QStringList out;
        if (!ok[0] || !ok[1] || !ok[2] || step <= 0)
            return out;
        // One past the cap, so that the caller says the rest was skipped.
        for (qint64 i = start; i <= stop && out.size() <= kMaxForeachItems; i += step)
            out << QString::number(i);
        return out;
    }
    if (rawArgs.value(0) != QLatin1String("IN"))
        return expandArgs(rawArgs);
    QStringList out;
    enum class Mode
    {
        None,
        Lists,
        Items
    } mode = Mode::None;
    for (const QString &a : rawArgs.mid(1)) {
        if (a == QLatin1String("LISTS"))
            mode = Mode::Lists;
        else if (a == QLatin1String("ITEMS"))
            mode = Mode::Items;
        else if (a == QLatin1String("ZIP_LISTS"))
            return {}; // several variables at once: not followed
        else if (mode == Mode::Lists)
            out << m_vars.value(expand(a)).split(QLatin1Char(';'), Qt::SkipEmptyParts);
        else if (mode == Mode::Items)
            out << expandArgs({a});
    }
    return out;
}

bool CMakeListsReader::valueTooLarge(const Evidence &where, QList<Diagnostic> *diagnostics)
{
    if (!m_valueTooLarge)
        return false;
    m_valueTooLarge = false;
    const QString place = where.file + QLatin1Char(':') + QString::number(where.line);
    if (m_valueLimitSaid.contains(place))
        return true; // once per command: a loop repeats it
    m_valueLimitSaid.insert(place);
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.code = QStringLiteral("evaluation-limit");
    d.message = QStringLiteral("A value in %1 grows past %2 characters (a variable built from "
                               "itself, doubled in a loop?); the command was skipped and the "
                               "variable left empty.")
                    .arg(m_file)
                    .arg(kMaxValueChars);
    d.evidence = where;
    diagnostics->append(d);
    return true;
}

QString CMakeListsReader::expand(const QString &text) const
{
    static const QRegularExpression var(QStringLiteral("\\$\\{([A-Za-z0-9_]+)\\}"));
    QString s = text;
    for (int round = 0; round < 5 && s.contains(QLatin1String("${")); ++round) {
        QString next;
        qsizetype last = 0;
        auto it = var.globalMatch(s);
        while (it.hasNext()) {
            const auto m = it.next();
            next += s.mid(last, m.capturedStart() - last);
            next += m_vars.value(m.captured(1));
            last = m.capturedEnd();
            if (next.size() > kMaxValueChars)
                break;
        }
        next += s.mid(last);
        if (next.size() > kMaxValueChars) {
            m_valueTooLarge = true; // said by execute(), which knows the command
            return {};
        }
        if (next == s)
            break;
        s = next;
    }
    return s;
}

QStringList CMakeListsReader::expandArgs(const QStringList &args) const
{
    QStringList out;
    for (const QString &a : args) {
        const QString e = expand(a);
        // A variable holding a list expands to several arguments.
        for (const QString &part : e.split(QLatin1Char(';'), Qt::SkipEmptyParts))
            out.append(part);
    }
    return out;
}

QList<Executable> CMakeListsReader::read(const QString &file, QList<Diagnostic> *diagnostics)
{
    m_vars.clear();
    m_targetSources.clear();
    m_executables.clear();
    m_plugins.clear();
    m_functions.clear();
    m_read.clear();
    m_valueLimitSaid.clear();
    m_bodyRuns = 0;
    readFile(file, 0, diagnostics);
    // A plugin registered on a library target is implemented by that target's sources.
    for (Executable &p : m_plugins) {
        p.sources = m_targetSources.value(p.target);
        m_executables.append(p);
    }
    for (Executable &e : m_executables)
        if (e.kind == Executable::Kind::CMakeExecutable)
            e.sources = m_targetSources.value(e.target, e.sources);
    return m_executables;
}

void CMakeListsReader::readFile(const QString &file, int depth, QList<Diagnostic> *diagnostics)
{
    QByteArray content;
    m_read.insert(QDir::cleanPath(file));
    if (!m_load(file, &content))
        return;
    m_file = file;
    m_dir = QFileInfo(file).path() == QLatin1String(".") ? QString() : QFileInfo(file).path();
    execute(tokenize(content), depth, diagnostics);
}

void CMakeListsReader::execute(const QList<Command> &commands, int depth,
                               QList<Diagnostic> *diagnostics)
{
    const QString file = m_file;
    const QString dir = m_dir;
    auto evidence = [&](const Command &c) {
        Evidence e;
        e.file = file;
        e.line = c.line;
        e.column = 1;
        e.endLine = c.endLine;
        e.endColumn = 1;
        return e;
    };
    for (qsizetype index = 0; index < commands.size(); ++index) {
        const Command &c = commands[index];
        if ((c.name == QLatin1String("function") || c.name == QLatin1String("macro")) &&
            !c.args.isEmpty()) {
            // Record the body; it runs when the function is called.
            Function f;
            f.params = c.args.mid(1);
            f.body = blockBody(commands, &index);
            m_functions.insert(c.args.first().toLower(), f);
            continue;
        }
        if (c.name == QLatin1String("foreach") && !c.args.isEmpty()) {
            // The body runs once per item, the loop variable set to it (as CMake does, and
            // restored after): `add_executable(${name} ${name}.cpp)` over a list of names.
            const QList<Command> body = blockBody(commands, &index);
            if (depth >= kMaxSubdirectoryDepth)
                continue;
            QStringList items = foreachItems(c.args.mid(1));
            if (items.size() > kMaxForeachItems) {
                notFollowed(QStringLiteral("A foreach loop in %1 runs over more than %2 items; "
                                           "only the first %2 were followed.")
                                .arg(file)
                                .arg(kMaxForeachItems),
                            evidence(c), diagnostics);
                items = items.mid(0, kMaxForeachItems);
            }
            const QString variable = expand(c.args.first());
            const std::optional<QString> saved =
                m_vars.contains(variable) ? std::optional(m_vars.value(variable)) : std::nullopt;
            for (const QString &item : std::as_const(items)) {
                if (!takeBodyRun(evidence(c), diagnostics))
                    break;
                m_vars.insert(variable, item);
                execute(body, depth + 1, diagnostics);
            }
            if (saved)
                m_vars.insert(variable, *saved);
            else
                m_vars.remove(variable);
            continue;
        }
        const QStringList args = expandArgs(c.args);
        if (valueTooLarge(evidence(c), diagnostics))
            continue;
        if (m_functions.contains(c.name)) {
            if (depth >= kMaxSubdirectoryDepth || !takeBodyRun(evidence(c), diagnostics))
                continue;
            const Function f = m_functions.value(c.name);
            const QHash<QString, QString> saved = m_vars;
            for (qsizetype k = 0; k < f.params.size(); ++k)
                m_vars.insert(f.params[k], args.value(k));
            m_vars.insert(QStringLiteral("ARGN"), args.mid(f.params.size()).join(QLatin1Char(';')));
            execute(f.body, depth + 1, diagnostics);
            m_vars = saved;
            continue;
        }
        if (c.name == QLatin1String("cmake_parse_arguments") && args.size() >= 4) {
            parseArguments(c.args);
            continue;
        }
        if (c.name == QLatin1String("project") && !args.isEmpty()) {
            m_vars.insert(QStringLiteral("PROJECT_NAME"), args.first());
        } else if (c.name == QLatin1String("set") && !args.isEmpty()) {
            QStringList values = args.mid(1);
            while (!values.isEmpty() && (values.last() == QLatin1String("PARENT_SCOPE") ||
                                         values.last() == QLatin1String("CACHE")))
                values.removeLast();
            const qsizetype cache = values.indexOf(QStringLiteral("CACHE"));
            if (cache >= 0)
                values = values.mid(0, cache);
            QString value = values.join(QLatin1Char(';'));
            if (value.size() > kMaxValueChars) {
                m_valueTooLarge = true;
                valueTooLarge(evidence(c), diagnostics);
                value.clear();
            }
            m_vars.insert(args.first(), value);
        } else if ((c.name == QLatin1String("add_executable") ||
                    c.name == QLatin1String("ament_auto_add_executable") ||
                    c.name == QLatin1String("add_library") ||
                    c.name == QLatin1String("ament_auto_add_library") ||
                    c.name == QLatin1String("target_sources")) &&
                   !args.isEmpty()) {
            QStringList sources;
            for (const QString &a : args.mid(1))
                if (isSourceFile(a))
                    sources.append(joinPath(dir, a));
            const QString &target = args.first();
            if (args.size() > 1 &&
                (args[1] == QLatin1String("ALIAS") || args[1] == QLatin1String("IMPORTED")))
                continue;
            m_targetSources[target].append(sources);
            if (c.name == QLatin1String("add_executable") ||
                c.name == QLatin1String("ament_auto_add_executable")) {
                Executable e;
                e.kind = Executable::Kind::CMakeExecutable;
                e.name = target;
                e.target = target;
                e.evidence = evidence(c);
                m_executables.append(e);
            }
        } else if (c.name == QLatin1String("set_target_properties") && args.size() >= 4) {
            // set_target_properties(tgt PROPERTIES OUTPUT_NAME name): the installed name.
            const qsizetype k = args.indexOf(QStringLiteral("OUTPUT_NAME"));
            if (k > 0 && k + 1 < args.size())
                for (Executable &e : m_executables)
                    if (e.target == args.first())
                        e.name = args[k + 1];
        } else if (c.name == QLatin1String("rclcpp_components_register_node") && !args.isEmpty()) {
            Executable e;
            e.kind = Executable::Kind::ComponentPlugin;
            e.target = args.first();
            const qsizetype p = args.indexOf(QStringLiteral("PLUGIN"));
            const qsizetype x = args.indexOf(QStringLiteral("EXECUTABLE"));
            if (p < 0 || p + 1 >= args.size())
                continue;
            e.plugin = args[p + 1];
            e.name = (x >= 0 && x + 1 < args.size()) ? args[x + 1] : QString();
            e.evidence = evidence(c);
            m_plugins.append(e);
        } else if (c.name == QLatin1String("rclcpp_components_register_nodes") && args.size() > 1) {
            for (const QString &plugin : args.mid(1)) {
                if (plugin == QLatin1String("RESOURCE_INDEX"))
                    break;
                Executable e;
                e.kind = Executable::Kind::ComponentPlugin;
                e.target = args.first();
                e.plugin = plugin;
                e.evidence = evidence(c);
                m_plugins.append(e);
            }
        } else if (c.name == QLatin1String("add_subdirectory") && !args.isEmpty()) {
            if (depth >= kMaxSubdirectoryDepth) {
                notFollowed(QStringLiteral("add_subdirectory nested deeper than %1 levels in %2; "
                                           "not followed.")
                                .arg(kMaxSubdirectoryDepth)
                                .arg(file),
                            evidence(c), diagnostics);
                continue;
            }
            const QString sub =
                joinPath(joinPath(dir, args.first()), QStringLiteral("CMakeLists.txt"));
            if (m_read.contains(sub)) {
                notFollowed(QStringLiteral("add_subdirectory(%1) in %2 names %3, which was "
                                           "already read; not read again.")
                                .arg(args.first(), file, sub),
                            evidence(c), diagnostics);
                continue;
            }
            readFile(sub, depth + 1, diagnostics);
            m_file = file;
            m_dir = dir;
        }
    }
}

} // namespace rosarch

namespace rosarch {

void CMakeListsReader::parseArguments(const QStringList &rawArgs)
{
    // cmake_parse_arguments(<prefix> <options> <one_value_keywords> <multi_value_keywords>
    // <args>...)
    const QString prefix = expand(rawArgs[0]);
    const QStringList options = expand(rawArgs[1]).split(QLatin1Char(';'), Qt::SkipEmptyParts);
    const QStringList single = expand(rawArgs[2]).split(QLatin1Char(';'), Qt::SkipEmptyParts);
    const QStringList multi = expand(rawArgs[3]).split(QLatin1Char(';'), Qt::SkipEmptyParts);
    QStringList values;
    for (const QString &a : rawArgs.mid(4))
        values.append(expand(a).split(QLatin1Char(';'), Qt::SkipEmptyParts));
    for (const QString &k : options + single + multi)
        m_vars.insert(prefix + QLatin1Char('_') + k, QString());
    QString current;
    QStringList collected;
    auto flush = [&]() {
        if (!current.isEmpty())
            m_vars.insert(prefix + QLatin1Char('_') + current, collected.join(QLatin1Char(';')));
        current.clear();
        collected.clear();
    };
    for (const QString &v : values) {
        if (options.contains(v)) {
            flush();
            m_vars.insert(prefix + QLatin1Char('_') + v, QStringLiteral("TRUE"));
        } else if (single.contains(v) || multi.contains(v)) {
            flush();
            current = v;
        } else if (!current.isEmpty()) {
            collected.append(v);
            if (single.contains(current))
                flush();
        }
    }
    flush();
}

} // namespace rosarch
