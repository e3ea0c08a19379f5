#include "workspace/workspacescanner.h"
#include "core/packageversion.h"
#include "workspace/buildfileparser.h"
#include "workspace/cmakelistsreader.h"
#include "workspace/sourcereader.h"

#include "cache/analysiscache.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QSet>

#include <algorithm>
#include <cerrno>
#include <functional>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>

namespace rosarch {

namespace {

bool isSkippedFolder(const QString &name)
{
    static const QSet<QString> skipped{QStringLiteral("build"), QStringLiteral("install"),
                                       QStringLiteral("log"), QStringLiteral("node_modules"),
                                       QStringLiteral("__pycache__")};
    return name.startsWith(QLatin1Char('.')) || skipped.contains(name);
}

SourceFile::Language languageOf(const QString &fileName)
{
    if (fileName == QLatin1String("package.xml"))
        return SourceFile::Language::PackageXml;
    if (fileName == QLatin1String("setup.py"))
        return SourceFile::Language::SetupPy;
    if (fileName == QLatin1String("setup.cfg"))
        return SourceFile::Language::SetupCfg;
    if (fileName == QLatin1String("CMakeLists.txt"))
        return SourceFile::Language::CMake;
    const QString suffix = QFileInfo(fileName).suffix().toLower();
    if (suffix == QLatin1String("py"))
        return SourceFile::Language::Python;
    if (suffix == QLatin1String("xml"))
        return SourceFile::Language::Xml; // launch files are told apart by content later
    // RViz configurations are YAML: what they display are observability outputs.
    if (suffix == QLatin1String("yaml") || suffix == QLatin1String("yml") ||
        suffix == QLatin1String("rviz"))
        return SourceFile::Language::Yaml;
    static const QSet<QString> cpp{
        QStringLiteral("cpp"), QStringLiteral("cc"), QStringLiteral("cxx"), QStringLiteral("hpp"),
        QStringLiteral("h"),   QStringLiteral("hh"), QStringLiteral("hxx"), QStringLiteral("ipp")};
    if (cpp.contains(suffix))
        return SourceFile::Language::Cpp;
    return SourceFile::Language::Other;
}

/// A folder's entry as readdir() gives it: the name, and the type when the file system says it
/// (DT_UNKNOWN otherwise).
struct DirEntry
{
    QString name;
    unsigned char type = DT_UNKNOWN;
    SourceFile::Language language = SourceFile::Language::Other; ///< Other for folders
    /// A regular source file's size, stat'ed relative to the open folder while listing it (a
    /// stat by full path walks every folder of the path again); -1 when it is gone by then.
    qint64 size = -1;
};

/// What one pass over a folder's listing finds.
struct Listing
{
    bool opened = false;
    bool ignored = false;    ///< a COLCON_IGNORE or AMENT_IGNORE is there
    QList<DirEntry> entries; ///< sorted by name, without "." and ".."
    QStringList undecodable; ///< names that are not valid UTF-8, decoded lossily, sorted
};

bool existsAt(int dirFd, const char *name)
{
    struct stat st
    {
    };
    return fstatat(dirFd, name, &st, 0) == 0;
}

/// The folder's entries in one readdir() pass: no stat per entry (the type comes with the
/// name on the usual file systems) but one for each source file's size, relative to the
/// folder, and the ignore markers seen in the listing.
Listing list(const QString &dir)
{
    Listing out;
    const QByteArray path = QFile::encodeName(dir);
    DIR *d = opendir(path.constData());
    if (!d) { // a folder that can be entered but not listed may still say to ignore it
        struct stat st
        {
        };
        out.ignored = stat((path + "/COLCON_IGNORE").constData(), &st) == 0 ||
                      stat((path + "/AMENT_IGNORE").constData(), &st) == 0;
        return out;
    }
    out.opened = true;
    const int fd = dirfd(d);
    while (const dirent *e = readdir(d)) {
        const char *raw = e->d_name;
        if (raw[0] == '.' && (raw[1] == '\0' || (raw[1] == '.' && raw[2] == '\0')))
            continue;
        const QByteArray name(raw);
        if (!name.isValidUtf8()) { // Qt's listings leave these out; they are said, not dropped
            out.undecodable << QString::fromUtf8(name);
            continue;
        }
        if ((name == "COLCON_IGNORE" || name == "AMENT_IGNORE") &&
            ((e->d_type != DT_LNK && e->d_type != DT_UNKNOWN) || existsAt(fd, raw)))
            out.ignored = true; // a marker is one when it exists (a dangling link is none)
        DirEntry entry{QString::fromUtf8(name), e->d_type};
        struct stat st
        {
        };
        if (entry.type == DT_UNKNOWN) { // the file system does not say: ask
            if (fstatat(fd, raw, &st, AT_SYMLINK_NOFOLLOW) != 0)
                continue;
            entry.type = S_ISDIR(st.st_mode)   ? DT_DIR
                         : S_ISLNK(st.st_mode) ? DT_LNK
                         : S_ISREG(st.st_mode) ? DT_REG
                                               : DT_UNKNOWN;
        }
        if (entry.type != DT_DIR)
            entry.language = languageOf(entry.name);
        if (entry.type == DT_REG && entry.language != SourceFile::Language::Other &&
            fstatat(fd, raw, &st, 0) == 0 && S_ISREG(st.st_mode))
            entry.size = st.st_size;
        out.entries.append(entry);
    }
    closedir(d);
    std::sort(out.entries.begin(), out.entries.end(),
              [](const DirEntry &a, const DirEntry &b) { return a.name < b.name; });
    out.undecodable.sort();
    return out;
}

class Walker
{
public:
    Walker(const QString &root, const StageControl &control, Workspace *ws)
        : m_root(root), m_control(control), m_ws(ws)
    {
    }

    /// Walks `absDir`, whose canonical path is `canonical` when the caller knows it (a real
    /// folder below a canonical one), else "" (the root, a symlink), then resolved here.
    void walk(const QString &absDir, const QString &relDir, QString canonical = QString(),
              int depth = 0)
    {
        if (m_control.isCanceled())
            return;
        if (depth > kMaxDepth) {
            skip(QStringLiteral("nesting-too-deep"),
                 QStringLiteral("Skipped %1: folders nest deeper than %2 levels here.")
                     .arg(relDir)
                     .arg(kMaxDepth),
                 relDir);
            return;
        }
        if (canonical.isEmpty())
            canonical = QFileInfo(absDir).canonicalFilePath();
        if (!canonical.isEmpty() && !isInside(canonical)) {
            skip(QStringLiteral("symlink-outside"),
                 QStringLiteral("Skipped %1: it links to %2, outside the workspace.")
                     .arg(relDir, canonical),
                 relDir);
            return;
        }
        if (canonical.isEmpty() || m_visited.contains(canonical)) {
            Diagnostic d;
            d.code = QStringLiteral("symlink-loop");
            d.message =
                canonical.isEmpty()
                    ? QStringLiteral("Skipped %1: the folder cannot be resolved (broken link?).")
                          .arg(relDir)
                    : QStringLiteral("Skipped %1: it links back to a folder already scanned "
                                     "(symlink loop or duplicate).")
                          .arg(relDir);
            d.evidence.file = relDir;
            m_ws->diagnostics.append(d);
            return;
        }
        m_visited.insert(canonical);
        const Listing listing = list(absDir);
        if (listing.ignored)
            return;
        if (!listing.opened) {
            Diagnostic d;
            d.code = QStringLiteral("unreadable-folder");
            d.message = QStringLiteral("Skipped %1: the folder cannot be read.").arg(relDir);
            d.evidence.file = relDir;
            m_ws->diagnostics.append(d);
            return;
        }
        for (const QString &name : listing.undecodable) {
            const QString rel = relDir.isEmpty() ? name : relDir + QLatin1Char('/') + name;
            skip(QStringLiteral("unreadable-name"),
                 QStringLiteral("Skipped %1: its name is not valid UTF-8 (shown with \uFFFD), so "
                                "it cannot be opened by name; rename it to analyse it.")
                     .arg(rel),
                 rel);
        }
        for (const DirEntry &e : listing.entries) {
            const QString rel = relDir.isEmpty() ? e.name : relDir + QLatin1Char('/') + e.name;
            const QString abs = absDir + QLatin1Char('/') + e.name;
            const unsigned char type = e.type;
            struct stat st
            {
            };
            if (type == DT_DIR) { // a real folder: its canonical path follows from its parent's
                if (!isSkippedFolder(e.name))
                    walk(abs, rel, canonical + QLatin1Char('/') + e.name, depth + 1);
                continue;
            }
            const bool link = type == DT_LNK;
            if (link && stat(QFile::encodeName(abs).constData(), &st) != 0) {
                if (e.language != SourceFile::Language::Other)
                    skip(
                        QStringLiteral("special-file"),
                        errno == ELOOP
                            ? QStringLiteral("Skipped %1: it is a symbolic link that never reaches "
                                             "a file (a link loop).")
                                  .arg(rel)
                            : QStringLiteral("Skipped %1: it is a symbolic link to %2, which "
                                             "does not exist.")
                                  .arg(rel, QFile::symLinkTarget(abs)),
                        rel);
                continue;
            }
            if (link && S_ISDIR(st.st_mode)) {
                if (!isSkippedFolder(e.name))
                    walk(abs, rel, QString(), depth + 1);
                continue;
            }
            if (link) {
                const QString target = QFileInfo(abs).canonicalFilePath();
                if (!isInside(target)) {
                    skip(QStringLiteral("symlink-outside"),
                         QStringLiteral("Skipped %1: it links to %2, outside the workspace.")
                             .arg(rel, target),
                         rel);
                    continue;
                }
            }
            const SourceFile::Language lang = e.language;
            if (lang == SourceFile::Language::Other)
                continue;
            // Fifos, sockets and devices are never opened: reading one could block forever.
            if (type != DT_REG && !link) {
                skipSpecial(rel, type == DT_FIFO   ? QStringLiteral("a named pipe (FIFO)")
                                 : type == DT_SOCK ? QStringLiteral("a socket")
                                                   : QStringLiteral("a device or special file"));
                continue;
            }
            if (!link && e.size < 0)
                continue; // gone since the listing, or no longer a regular file
            if (link && !S_ISREG(st.st_mode)) {
                skipSpecial(rel, S_ISFIFO(st.st_mode)   ? QStringLiteral("a link to a named pipe")
                                 : S_ISSOCK(st.st_mode) ? QStringLiteral("a link to a socket")
                                                        : QStringLiteral("a link to a device"));
                continue;
            }
            SourceFile f;
            f.path = rel;
            f.language = lang;
            f.size = link ? st.st_size : e.size;
            m_ws->files.append(f);
        }
    }

private:
    static constexpr int kMaxDepth = 100;

    bool isInside(const QString &canonical) const
    {
        return canonical == m_canonicalRoot ||
               canonical.startsWith(m_canonicalRoot + QLatin1Char('/'));
    }

    /// A file where a source, launch or package file is expected that is no regular file.
    void skipSpecial(const QString &rel, const QString &what)
    {
        skip(QStringLiteral("special-file"),
             QStringLiteral("Skipped %1: it is %2, not a regular file, so it was not read.")
                 .arg(rel, what),
             rel);
    }

    void skip(const QString &code, const QString &message, const QString &rel)
    {
        Diagnostic d;
        d.code = code;
        d.message = message;
        d.evidence.file = rel;
        m_ws->diagnostics.append(d);
    }

    QString m_root;
    QString m_canonicalRoot = QFileInfo(m_root).canonicalFilePath();
    const StageControl &m_control;
    Workspace *m_ws;
    QSet<QString> m_visited;
};

QString parentDir(const QString &relPath)
{
    const qsizetype slash = relPath.lastIndexOf(QLatin1Char('/'));
    return slash < 0 ? QString() : relPath.left(slash);
}

/// A file the package phase looked at, and what it held then: its digest ("" when it could not
/// be read) and whether it existed.
struct Looked
{
    QString path;
    QByteArray digest;
    bool exists = false;
    bool operator==(const Looked &) const = default;
};

/// What a scan found past its walk, for the next scan of the same workspace in this process:
/// when that walk finds the same and the build files looked at are unchanged, so is the rest.
struct ScanMemo
{
    QString root;
    QList<SourceFile> walked;
    QList<Diagnostic> walkDiagnostics;
    QHash<QString, QString> skipped;
    QList<Looked> looked;
    Workspace result;
};

/// The same files, apart from their sizes (which the package phase does not read).
bool sameFiles(const QList<SourceFile> &a, const QList<SourceFile> &b)
{
    if (a.size() != b.size())
        return false;
    for (qsizetype i = 0; i < a.size(); ++i)
        if (a.at(i).path != b.at(i).path || a.at(i).language != b.at(i).language)
            return false;
    return true;
}

Looked look(const Workspace &ws, const QString &rel, FileDigests &digests)
{
    const QString abs = ws.absolutePath(rel);
    Looked l{rel, digests.digest(abs), false};
    l.exists = !l.digest.isEmpty() || QFileInfo::exists(abs);
    return l;
}

/// Two folders that declare one package name: colcon refuses to build such a workspace, and
/// every name lookup would pick one copy or the other. The analysis keeps one copy, the newer
/// `<version>` (the first by path when they agree), as if the other had a COLCON_IGNORE, and
/// says so in an error that names both. `ws.packages` is sorted by name, then path.
void dropDuplicatePackages(Workspace &ws, const std::function<RosPackage *(const QString &)> &owner)
{
    QSet<QString> dropped; // package folders
    for (qsizetype i = 0; i < ws.packages.size();) {
        qsizetype end = i + 1;
        while (end < ws.packages.size() && ws.packages.at(end).name == ws.packages.at(i).name)
            ++end;
        qsizetype kept = i;
        for (qsizetype j = i + 1; j < end; ++j)
            if (compareVersions(ws.packages.at(j).version, ws.packages.at(kept).version) > 0)
                kept = j;
        for (qsizetype j = i; j < end; ++j) {
            if (j == kept)
                continue;
            const RosPackage &used = ws.packages.at(kept), &other = ws.packages.at(j);
            const auto where = [](const RosPackage &p) {
                return p.path.isEmpty() ? QStringLiteral(".") : p.path;
            };
            const auto version = [](const RosPackage &p) {
                return p.version.isEmpty() ? QString()
                                           : QStringLiteral(" (version %1)").arg(p.version);
            };
            Diagnostic d;
            d.severity = Diagnostic::Severity::Error;
            d.code = QStringLiteral("duplicate-package");
            d.message = QStringLiteral("The package %1 is declared twice: here%2 and in %3%4. "
                                       "colcon refuses to build both; the analysis uses %3, %5, "
                                       "and ignores this copy. Remove one, or put a "
                                       "COLCON_IGNORE file in the copy you do not build.")
                            .arg(used.name, version(other), where(used), version(used),
                                 compareVersions(used.version, other.version) > 0
                                     ? QStringLiteral("the newer version")
                                     : QStringLiteral("the first by path"));
            d.evidence = other.evidence;
            d.related.append({QStringLiteral("the copy the analysis uses"), used.evidence});
            ws.diagnostics.append(d);
            dropped.insert(other.path);
        }
        i = end;
    }
    if (dropped.isEmpty())
        return;
    ws.files.removeIf([&](const SourceFile &f) {
        const RosPackage *p = owner(f.path);
        return p && dropped.contains(p->path);
    });
    ws.packages.removeIf([&](const RosPackage &p) { return dropped.contains(p.path); });
}

/// The packages (one per package.xml; its folder owns every file below it) and what their
/// build files declare. Each file looked at is added to `looked` (when given), with what it held
/// before it was read: a change after that is seen by the next scan.
void readPackages(Workspace &ws, const StageControl &control, FileDigests *digests,
                  QList<Looked> *looked)
{
    const SourceReader reader(ws.root);
    auto note = [&](const QString &rel) {
        if (digests)
            looked->append(look(ws, rel, *digests));
    };
    auto exists = [&](const QString &rel) {
        note(rel);
        return QFileInfo::exists(ws.absolutePath(rel));
    };
    auto load = [&](const QString &rel, QByteArray *content) {
        if (!exists(rel))
            return false;
        return reader.read(rel, content, &ws.diagnostics);
    };

    for (const SourceFile &f : std::as_const(ws.files)) {
        if (f.language != SourceFile::Language::PackageXml)
            continue;
        if (control.isCanceled())
            return; // what was read so far: a canceled scan's workspace is not used
        RosPackage pkg;
        pkg.path = parentDir(f.path);
        const FileWork work(control, f.path);
        QByteArray content;
        if (!work.skip(&ws.diagnostics) && load(f.path, &content))
            BuildFileParser::readPackageXml(content, f.path, &pkg, &ws.diagnostics);
        if (pkg.name.isEmpty())
            pkg.name = QFileInfo(pkg.path.isEmpty() ? ws.root : pkg.path).fileName();
        ws.packages.append(pkg);
    }
    std::sort(ws.packages.begin(), ws.packages.end(), [](const RosPackage &a, const RosPackage &b) {
        return a.name < b.name || (a.name == b.name && a.path < b.path);
    });

    // A file's package is the one in the nearest folder above it: its folders are looked up
    // from the innermost out (a loop over the packages per file took autoware's scan ~40 ms).
    QHash<QString, RosPackage *> byFolder;
    byFolder.reserve(ws.packages.size());
    for (RosPackage &p : ws.packages)
        byFolder.insert(p.path, &p);
    auto owner = [&](const QString &relPath) -> RosPackage * {
        for (qsizetype slash = relPath.lastIndexOf(QLatin1Char('/')); slash > 0;
             slash = relPath.lastIndexOf(QLatin1Char('/'), slash - 1)) {
            if (RosPackage *p = byFolder.value(relPath.left(slash)))
                return p;
        }
        return byFolder.value(QString());
    };
    for (SourceFile &f : ws.files)
        if (RosPackage *p = owner(f.path))
            f.package = p->name;
    dropDuplicatePackages(ws, owner);

    // Build files at a package's root declare its executables and plugins.
    for (RosPackage &pkg : ws.packages) {
        if (control.isCanceled())
            return;
        const QString prefix = pkg.path.isEmpty() ? QString() : pkg.path + QLatin1Char('/');
        QByteArray content;
        if (const FileWork work(control, prefix + QStringLiteral("setup.py"));
            !work.skip(&ws.diagnostics) && load(prefix + QStringLiteral("setup.py"), &content))
            pkg.executables.append(BuildFileParser::readSetupPy(
                content, prefix + QStringLiteral("setup.py"), &ws.diagnostics));
        if (load(prefix + QStringLiteral("setup.cfg"), &content))
            pkg.executables.append(
                BuildFileParser::readSetupCfg(content, prefix + QStringLiteral("setup.cfg")));
        if (const FileWork work(control, prefix + QStringLiteral("CMakeLists.txt"));
            exists(prefix + QStringLiteral("CMakeLists.txt")) && !work.skip(&ws.diagnostics)) {
            CMakeListsReader cmake(load);
            pkg.executables.append(
                cmake.read(prefix + QStringLiteral("CMakeLists.txt"), &ws.diagnostics));
        }
    }
}

} // namespace

Workspace WorkspaceScanner::scan(const QString &root, const StageControl &control)
{
    Workspace ws;
    const QFileInfo rootInfo(root);
    ws.root = rootInfo.canonicalFilePath().isEmpty() ? rootInfo.absoluteFilePath()
                                                     : rootInfo.canonicalFilePath();
    if (!rootInfo.isDir()) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Error;
        d.code = QStringLiteral("no-workspace");
        d.message = QStringLiteral("%1 is not a folder.").arg(root);
        ws.diagnostics.append(d);
        return ws;
    }
    control.report(0, 0, QStringLiteral("Scanning %1").arg(ws.root));
    Walker(ws.root, control, &ws).walk(ws.root, QString());
    std::sort(ws.files.begin(), ws.files.end(),
              [](const SourceFile &a, const SourceFile &b) { return a.path < b.path; });

    // In a long-lived process, the previous scan's packages when nothing they came from changed.
    AnalysisCache &cache = AnalysisCache::of(control);
    const bool memo = cache.isEnabled() && !control.isCanceled();
    const QString kind = QStringLiteral("scan");
    const QByteArray key("last");
    if (memo) {
        if (const std::shared_ptr<const void> kept = cache.recent(kind, key)) {
            const ScanMemo &m = *static_cast<const ScanMemo *>(kept.get());
            const auto unchanged = [&] {
                for (const Looked &l : m.looked)
                    if (!(look(ws, l.path, cache.digests()) == l))
                        return false;
                return true;
            };
            if (m.root == ws.root && m.skipped == control.skipped &&
                sameFiles(m.walked, ws.files) && m.walkDiagnostics == ws.diagnostics &&
                unchanged()) {
                Workspace out = m.result;
                for (qsizetype i = 0; i < out.files.size(); ++i) // an edit changes a file's size
                    if (out.files.at(i).size != ws.files.at(i).size)
                        out.files[i].size = ws.files.at(i).size;
                return out;
            }
        }
    }
    ScanMemo next{ws.root, ws.files, ws.diagnostics, control.skipped, {}, {}};
    readPackages(ws, control, memo ? &cache.digests() : nullptr, &next.looked);
    if (memo && !control.isCanceled()) {
        next.result = ws;
        cache.keepRecent(kind, key, std::make_shared<const ScanMemo>(std::move(next)));
    }
    return ws;
}

} // namespace rosarch
