#include "nodes/cpp/cppmacroindex.h"

#include "syntax/cppsyntax.h"
#include "workspace/cmakelistsreader.h"

#include <QFileInfo>

namespace rosarch {

namespace {

// What a Linux build with GCC in C++17 mode predefines, for `#ifdef __linux__` and the like.
CppMacros predefined()
{
    CppMacros m;
    for (const char *name : {"__linux__", "__linux", "__unix__", "__unix", "__STDC__"})
        m.insert(name, CppMacro{"1", {}, false});
    m.insert("__cplusplus", CppMacro{"201703L", {}, false});
    m.insert("__GNUC__", CppMacro{"11", {}, false});
    return m;
}

QString cleanPath(const QString &path)
{
    QStringList out;
    for (const QString &part : path.split(u'/')) {
        if (part.isEmpty() || part == QLatin1String("."))
            continue;
        if (part == QLatin1String("..")) {
            if (out.isEmpty())
                return {};
            out.removeLast();
        } else {
            out.append(part);
        }
    }
    return out.join(u'/');
}

} // namespace

CppMacroIndex::CppMacroIndex(const Workspace &workspace, const SourceReader &reader,
                             const StageControl &control)
    : m_workspace(&workspace), m_reader(&reader), m_control(&control)
{
    indexFiles(workspace, reader);
    for (const SourceFile &file : workspace.files) {
        if (control.isCanceled())
            break;
        if (file.language == SourceFile::Language::Cpp && cppsyntax::isHeaderPath(file.path))
            exportsOf(file.path, 0);
    }
    m_visiting.clear();
    m_control = nullptr;
}

CppMacroIndex::CppMacroIndex(const Workspace &workspace, const SourceReader &reader,
                             QHash<QString, CppMacros> exports)
    : m_workspace(&workspace), m_reader(&reader), m_exports(std::move(exports))
{
    indexFiles(workspace, reader);
}

void CppMacroIndex::indexFiles(const Workspace &workspace, const SourceReader &reader)
{
    for (const SourceFile &file : workspace.files) {
        if (file.language != SourceFile::Language::Cpp)
            continue;
        m_packageOf.insert(file.path, file.package);
        if (!cppsyntax::isHeaderPath(file.path))
            continue;
        // Every folder named include/ can be on the include path: pkg/include/pkg/x.hpp is
        // included as "pkg/x.hpp".
        for (qsizetype at = file.path.indexOf(QLatin1String("include/")); at >= 0;
             at = file.path.indexOf(QLatin1String("include/"), at + 1)) {
            if (at == 0 || file.path.at(at - 1) == u'/')
                m_byIncludePath[file.path.mid(at + 8)].append(file.path);
        }
    }
    for (const RosPackage &package : workspace.packages) {
        const QString cmake = package.path.isEmpty()
                                  ? QStringLiteral("CMakeLists.txt")
                                  : package.path + QStringLiteral("/CMakeLists.txt");
        QByteArray content;
        QList<Diagnostic> ignored; // the build files' own reader reports them
        if (QFileInfo::exists(workspace.absolutePath(cmake)) &&
            reader.read(cmake, &content, &ignored))
            m_packageDefinitions.insert(package.name, compileDefinitions(content));
    }
}

CppMacros CppMacroIndex::initialMacros(const QString &package) const
{
    CppMacros macros = predefined();
    const CppMacros definitions = m_packageDefinitions.value(package);
    for (auto it = definitions.cbegin(); it != definitions.cend(); ++it)
        macros.insert(it.key(), it.value());
    return macros;
}

QString CppMacroIndex::resolve(const QString &file, const QString &written, bool angled) const
{
    if (!angled) { // "x.hpp" is first looked for next to the including file
        const qsizetype slash = file.lastIndexOf(u'/');
        const QString local = cleanPath((slash < 0 ? QString() : file.left(slash + 1)) + written);
        if (!local.isEmpty() && m_packageOf.contains(local))
            return local;
    }
    const QStringList candidates = m_byIncludePath.value(cleanPath(written));
    if (candidates.isEmpty())
        return {};
    const QString package = m_packageOf.value(file);
    for (const QString &c : candidates) // the including package's own header first
        if (m_packageOf.value(c) == package)
            return c;
    return candidates.front();
}

CppPreprocessor::IncludeLookup CppMacroIndex::lookup(const QString &file) const
{
    return [this, file](const QByteArray &written, bool angled) -> const CppMacros * {
        const QString header = resolve(file, QString::fromUtf8(written), angled);
        const auto it = m_exports.constFind(header);
        return it == m_exports.constEnd() || it->isEmpty() ? nullptr : &*it;
    };
}

const CppMacros *CppMacroIndex::exportsOf(const QString &header, int depth)
{
    const auto known = m_exports.constFind(header);
    if (known != m_exports.constEnd())
        return &*known;
    if (m_visiting.contains(header) || depth > kMaxIncludeDepth || !m_control ||
        m_control->skipped.contains(header))
        return nullptr;
    const FileWork work(*m_control, header);
    QByteArray content;
    QList<Diagnostic> ignored; // reported when the file itself is analysed
    if (!m_reader->read(header, &content, &ignored)) {
        m_exports.insert(header, {});
        return nullptr;
    }
    m_visiting.insert(header);
    const CppPreprocessor::Result r = CppPreprocessor::run(
        &content, header, initialMacros(m_packageOf.value(header)),
        [this, header, depth](const QByteArray &written, bool angled) {
            const QString included = resolve(header, QString::fromUtf8(written), angled);
            return included.isEmpty() ? nullptr : exportsOf(included, depth + 1);
        });
    m_visiting.remove(header);
    return &*m_exports.insert(header, r.exported);
}

CppMacros CppMacroIndex::compileDefinitions(const QByteArray &cmakeLists)
{
    CppMacros macros;
    for (const CMakeListsReader::Command &c : CMakeListsReader::tokenize(cmakeLists)) {
        const bool all = c.name == QLatin1String("add_compile_definitions");
        const bool dashD = c.name == QLatin1String("add_definitions");
        const bool target = c.name == QLatin1String("target_compile_definitions");
        if (!all && !dashD && !target)
            continue;
        for (qsizetype i = target ? 1 : 0; i < c.args.size(); ++i) {
            QString arg = c.args.at(i);
            if (arg == QLatin1String("PUBLIC") || arg == QLatin1String("PRIVATE") ||
                arg == QLatin1String("INTERFACE"))
                continue;
            if (arg.startsWith(QLatin1String("-D")))
                arg = arg.mid(2);
            else if (dashD)
                continue; // add_definitions also takes other compiler flags
            if (arg.contains(u'$') || arg.isEmpty())
                continue; // a variable or a generator expression: not known here
            const qsizetype eq = arg.indexOf(u'=');
            const QString name = eq < 0 ? arg : arg.left(eq);
            bool identifier = !name.isEmpty() && !name.at(0).isDigit();
            for (QChar ch : name)
                identifier = identifier && (ch.isLetterOrNumber() || ch == u'_');
            if (!identifier)
                continue;
            macros.insert(name.toUtf8(),
                          CppMacro{eq < 0 ? QByteArray("1")
                                          : arg.mid(eq + 1)
                                                .replace(QLatin1String("\\\""), QLatin1String("\""))
                                                .toUtf8(),
                                   {},
                                   false});
        }
    }
    return macros;
}

} // namespace rosarch
