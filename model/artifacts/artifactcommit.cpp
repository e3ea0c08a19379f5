#include "artifacts/artifactcommit.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rosarch {

namespace {

QByteArray native(const QString &path)
{
    return QFile::encodeName(path);
}

QString systemError()
{
    return QString::fromLocal8Bit(std::strerror(errno));
}

/// The names in a folder, without "." and "..".
QStringList namesIn(const QString &dir)
{
    QStringList out;
    if (DIR *d = opendir(native(dir).constData())) {
        while (const dirent *e = readdir(d)) {
            const char *n = e->d_name;
            if (!(n[0] == '.' && (n[1] == '\0' || (n[1] == '.' && n[2] == '\0'))))
                out << QFile::decodeName(n);
        }
        closedir(d);
    }
    return out;
}

/// Removes `path` and everything below it, without following links.
void removeTree(const QString &path)
{
    struct stat st = {};
    if (lstat(native(path).constData(), &st) != 0)
        return;
    if (S_ISDIR(st.st_mode)) {
        for (const QString &name : namesIn(path))
            removeTree(path + QLatin1Char('/') + name);
        rmdir(native(path).constData());
    } else {
        unlink(native(path).constData());
    }
}

/// True when `path` holds exactly `content` (read only when the sizes agree).
bool holds(const QString &path, const QByteArray &content)
{
    struct stat st = {};
    if (stat(native(path).constData(), &st) != 0 || !S_ISREG(st.st_mode) ||
        st.st_size != content.size())
        return false;
    QFile f(path);
    return f.open(QIODevice::ReadOnly) && f.readAll() == content;
}

bool writeNew(const QString &path, const QByteArray &content)
{
    const int fd = ::open(native(path).constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        return false;
    qint64 done = 0;
    while (done < content.size()) {
        const ssize_t n = ::write(fd, content.constData() + done, size_t(content.size() - done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            const int why = n < 0 ? errno : ENOSPC;
            ::close(fd);
            errno = why;
            return false;
        }
        done += n;
    }
    return ::close(fd) == 0;
}

mode_t folderMode()
{
    const mode_t mask = umask(0);
    umask(mask);
    return 0777 & ~mask;
}

} // namespace

ArtifactCommit::ArtifactCommit(const QString &dir)
{
    QString clean = QDir::cleanPath(QFileInfo(dir).absoluteFilePath());
    m_dir = clean;
    m_parent = QFileInfo(clean).path();
    m_prefix = QStringLiteral(".%1.rosarch-writing-").arg(QFileInfo(clean).fileName());
}

ArtifactCommit::~ArtifactCommit()
{
    if (!m_staging.isEmpty())
        removeTree(m_staging);
}

bool ArtifactCommit::isArtifact(const QString &topName)
{
    static const QStringList ours = {QStringLiteral("atomic_nodes.json"),
                                     QStringLiteral("launch_dependencies.json"),
                                     QStringLiteral("architecture.json"),
                                     QStringLiteral("diagnostics.json"),
                                     QStringLiteral("acd"),
                                     QStringLiteral("ccd"),
                                     QStringLiteral("mermaid"),
                                     QStringLiteral("graph")};
    return ours.contains(topName) || topName == QLatin1String(kStampFile) ||
           topName.startsWith(QLatin1String(".rosarch-writing-"));
}

void ArtifactCommit::removeStale() const
{
    // A staging folder is named for the process that made it; one whose process is gone was
    // left by a killed run (a running one's is left alone: two runs may share a folder).
    for (const QString &name : namesIn(m_parent)) {
        if (!name.startsWith(m_prefix))
            continue;
        bool ok = false;
        const qint64 pid =
            name.mid(m_prefix.size()).section(QLatin1Char('-'), 0, 0).toLongLong(&ok);
        if (ok && pid > 0 && pid != getpid() && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH)
            removeTree(m_parent + QLatin1Char('/') + name);
    }
}

bool ArtifactCommit::begin(QString *error)
{
    if (!QDir().mkpath(m_dir)) {
        *error = QStringLiteral("Cannot create the folder %1.").arg(m_dir);
        return false;
    }
    removeStale();
    // The staging folder of an earlier version of rosarch, inside the output folder.
    for (const QString &name : namesIn(m_dir))
        if (name.startsWith(QLatin1String(".rosarch-writing-")))
            removeTree(m_dir + QLatin1Char('/') + name);
    m_inPlace = false;
    QByteArray pattern = native(m_parent + QLatin1Char('/') + m_prefix + QString::number(getpid()) +
                                QStringLiteral("-XXXXXX"));
    if (m_dir != m_parent && mkdtemp(pattern.data())) {
        m_staging = QFile::decodeName(pattern);
        chmod(pattern.constData(), folderMode());
        return true;
    }
    // The parent cannot be written (or the output folder is a root): stage inside the folder.
    pattern = native(m_dir + QStringLiteral("/.rosarch-writing-XXXXXX"));
    if (!mkdtemp(pattern.data())) {
        *error = QStringLiteral("Cannot write into %1: %2").arg(m_dir, systemError());
        return false;
    }
    m_staging = QFile::decodeName(pattern);
    m_inPlace = true;
    m_inPlaceReason = m_dir == m_parent ? QStringLiteral("the output folder is a root folder")
                                        : QStringLiteral("its parent folder cannot be written");
    return true;
}

bool ArtifactCommit::add(const QString &relative, const QByteArray &content, QString *error)
{
    const QString path = m_staging + QLatin1Char('/') + relative;
    const QString folder = QFileInfo(relative).path();
    if (folder != QLatin1String(".") && !m_folders.contains(folder)) {
        if (!QDir().mkpath(QFileInfo(path).path())) {
            *error = QStringLiteral("Cannot create the folder %1.")
                         .arg(m_dir + QLatin1Char('/') + folder);
            return false;
        }
        m_folders << folder;
    }
    const QString previous = m_dir + QLatin1Char('/') + relative;
    if (!m_inPlace && holds(previous, content) &&
        ::link(native(previous).constData(), native(path).constData()) == 0) {
        ++m_unchanged;
        m_files << relative;
        return true;
    }
    errno = 0;
    if (!writeNew(path, content)) {
        *error = QStringLiteral("Cannot write %1: %2").arg(previous, systemError());
        return false;
    }
    m_files << relative;
    return true;
}

bool ArtifactCommit::carryOver(const QString &from, const QString &to, int *budget) const
{
    if (--*budget < 0)
        return false;
    struct stat st = {};
    if (lstat(native(from).constData(), &st) != 0)
        return errno == ENOENT; // gone meanwhile
    if (S_ISDIR(st.st_mode)) {
        if (mkdir(native(to).constData(), st.st_mode & 07777) != 0)
            return false;
        for (const QString &name : namesIn(from))
            if (!carryOver(from + QLatin1Char('/') + name, to + QLatin1Char('/') + name, budget))
                return false;
        return true;
    }
    if (S_ISLNK(st.st_mode)) {
        QByteArray target(4096, '\0');
        const ssize_t n = readlink(native(from).constData(), target.data(), size_t(target.size()));
        return n > 0 && n < target.size() &&
               symlink(target.left(n).constData(), native(to).constData()) == 0;
    }
    return S_ISREG(st.st_mode) && ::link(native(from).constData(), native(to).constData()) == 0;
}

bool ArtifactCommit::syncFolders(QString *error) const
{
    // One fsync per folder, not one per file: the folder's entries are what the swap needs.
    QStringList folders = {QString()};
    for (const QString &f : m_folders)
        for (QString part = f; !part.isEmpty() && part != QLatin1String(".");
             part = QFileInfo(part).path())
            if (!folders.contains(part))
                folders << part;
    for (const QString &f : std::as_const(folders)) {
        const QString path = f.isEmpty() ? m_staging : m_staging + QLatin1Char('/') + f;
        const int fd = ::open(native(path).constData(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (fd < 0 || (::fsync(fd) != 0 && errno != EINVAL)) {
            *error = QStringLiteral("Cannot write into %1: %2").arg(m_dir, systemError());
            if (fd >= 0)
                ::close(fd);
            return false;
        }
        ::close(fd);
    }
    return true;
}

namespace {

/// "size mtime" of a file, as the stamp records it; "" when it is no regular file.
QByteArray fileStamp(const QString &path)
{
    struct stat st = {};
    if (stat(native(path).constData(), &st) != 0 || !S_ISREG(st.st_mode))
        return {};
    return QByteArray::number(qint64(st.st_size)) + ' ' +
           QByteArray::number(qint64(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec);
}

} // namespace

bool ArtifactCommit::writeStamp(const QByteArray &stamp, QString *error)
{
    // Renames and links keep a file's time: what is recorded here is what the folder will hold.
    QByteArray record = stamp + '\n';
    for (const QString &relative : std::as_const(m_files))
        record +=
            relative.toUtf8() + '\t' + fileStamp(m_staging + QLatin1Char('/') + relative) + '\n';
    const QString path = m_staging + QLatin1Char('/') + QLatin1String(kStampFile);
    if (!writeNew(path, record)) {
        *error = QStringLiteral("Cannot write %1: %2").arg(path, systemError());
        return false;
    }
    return true;
}

bool ArtifactCommit::unchanged(const QString &dir, const QByteArray &stamp, QStringList *written)
{
    if (stamp.isEmpty())
        return false;
    QFile f(dir + QLatin1Char('/') + QLatin1String(kStampFile));
    if (!f.open(QIODevice::ReadOnly))
        return false;
    const QList<QByteArray> lines = f.readAll().split('\n');
    if (lines.isEmpty() || lines.first() != stamp)
        return false;
    QStringList files;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        if (lines.at(i).isEmpty())
            continue;
        const qsizetype tab = lines.at(i).indexOf('\t');
        const QString path = dir + QLatin1Char('/') + QString::fromUtf8(lines.at(i).left(tab));
        if (tab < 0 || fileStamp(path) != lines.at(i).mid(tab + 1))
            return false;
        files << path;
    }
    if (written)
        written->append(files);
    return true;
}

bool ArtifactCommit::commit(QStringList *written, QString *error, const QByteArray &stamp)
{
    if (m_inPlace)
        return commitInPlace(written, error);
    if (!stamp.isEmpty() && !writeStamp(stamp, error))
        return false;
    int budget = kMaxCarried;
    QString notCarried;
    for (const QString &name : namesIn(m_dir))
        if (!isArtifact(name) && notCarried.isEmpty() &&
            !carryOver(m_dir + QLatin1Char('/') + name, m_staging + QLatin1Char('/') + name,
                       &budget))
            notCarried =
                budget < 0 ? QStringLiteral("it holds more than %1 other entries").arg(kMaxCarried)
                           : QStringLiteral("its entry %1 cannot be carried over (a "
                                            "special file, or another file system)")
                                 .arg(name);
    if (!syncFolders(error))
        return false;
    const bool swapped =
        notCarried.isEmpty() && renameat2(AT_FDCWD, native(m_staging).constData(), AT_FDCWD,
                                          native(m_dir).constData(), RENAME_EXCHANGE) == 0;
    if (swapped) {
        // The previous result is now in the staging folder's place.
        if (const int fd = ::open(native(m_parent).constData(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
            fd >= 0) {
            ::fsync(fd);
            ::close(fd);
        }
        removeTree(m_staging);
        m_staging.clear();
        if (written)
            for (const QString &relative : std::as_const(m_files))
                written->append(m_dir + QLatin1Char('/') + relative);
        return true;
    }
    // Not swappable here: move the fresh folder inside the output folder and go on in place.
    m_inPlaceReason =
        notCarried.isEmpty()
            ? QStringLiteral("the file system cannot exchange two folders: %1").arg(systemError())
            : notCarried;
    const QString inside = m_dir + QStringLiteral("/.rosarch-writing-%1").arg(getpid());
    removeTree(inside);
    for (const QString &name : namesIn(m_staging))
        if (!isArtifact(name))
            removeTree(m_staging + QLatin1Char('/') + name); // what was carried over
    if (std::rename(native(m_staging).constData(), native(inside).constData()) != 0) {
        *error = QStringLiteral("Cannot move the artifacts into %1: %2").arg(m_dir, systemError());
        return false;
    }
    m_staging = inside;
    m_inPlace = true;
    return commitInPlace(written, error);
}

bool ArtifactCommit::commitInPlace(QStringList *written, QString *error)
{
    QFile::remove(m_dir + QLatin1Char('/') + QLatin1String(kStampFile)); // files change one by one
    // Diagrams of an earlier run (and their pictures) would otherwise linger beside the new
    // ones; then each file replaces its old version by a rename.
    for (const QString &sub : {QStringLiteral("acd"), QStringLiteral("ccd"),
                               QStringLiteral("mermaid"), QStringLiteral("graph")}) {
        const QString folder = m_dir + QLatin1Char('/') + sub;
        for (const QString &name : namesIn(folder))
            if (QFileInfo(folder + QLatin1Char('/') + name).isFile())
                QFile::remove(folder + QLatin1Char('/') + name);
    }
    const QDir out(m_dir);
    for (const QString &relative : std::as_const(m_files)) {
        const QString target = out.filePath(relative);
        if (!out.mkpath(QFileInfo(relative).path()) ||
            std::rename(native(m_staging + QLatin1Char('/') + relative).constData(),
                        native(target).constData()) != 0) {
            *error = QStringLiteral("Cannot move %1 into place: %2").arg(target, systemError());
            return false;
        }
        if (written)
            written->append(target);
    }
    return true;
}

} // namespace rosarch
