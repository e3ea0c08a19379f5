#pragma once

#include <QString>
#include <QStringList>

namespace rosarch {

/// Puts a run's artifacts into an output folder so that, whenever the run is killed, the folder
/// holds the previous run's artifacts or this run's, never a mix:
///  1. begin() removes the staging folders that killed runs left beside the output folder, and
///     makes a fresh one;
///  2. add() writes each artifact there; a file equal to its previous version is hard-linked
///     from it instead (its time stamp stays, and nothing is written);
///  3. commit() hard-links what else the output folder holds (files that are not artifacts),
///     syncs each new folder once, and swaps the fresh folder with the output folder in one
///     rename (RENAME_EXCHANGE); the previous result is then removed.
/// Where that cannot be done (no RENAME_EXCHANGE, an output folder that is a mount point, more
/// than kMaxCarried entries to carry over), the artifacts are staged inside the output folder
/// and moved in one by one, the previous scheme: a failure still leaves the old ones intact.
class ArtifactCommit
{
public:
    explicit ArtifactCommit(const QString &dir);
    ~ArtifactCommit();
    ArtifactCommit(const ArtifactCommit &) = delete;
    ArtifactCommit &operator=(const ArtifactCommit &) = delete;

    /// Entries of the output folder carried over into the fresh one at most; past it, the
    /// artifacts are moved in one by one.
    static constexpr int kMaxCarried = 20000;

    bool begin(QString *error);
    /// Writes `content` as `relative` (a path below the output folder).
    bool add(const QString &relative, const QByteArray &content, QString *error);
    /// Puts every file added in place; `written` lists them (absolute paths in the output folder).
    /// `stamp` (a digest of what the artifacts were made from) is kept beside them, with each
    /// file's size and time, for unchanged().
    bool commit(QStringList *written, QString *error, const QByteArray &stamp = {});

    /// True when the output folder `dir` holds the artifacts of `stamp` as a commit left them:
    /// the same stamp, every file there with its size and time. Then nothing needs writing, and
    /// `written` lists the files. (A file edited or removed since makes it false.)
    static bool unchanged(const QString &dir, const QByteArray &stamp, QStringList *written);
    /// The name of that record in the output folder.
    static constexpr const char *kStampFile = ".rosarch-artifacts";

    /// True for the names at the top of an output folder that belong to the artifacts (and are
    /// replaced as a whole): the JSON files, the diagram folders, staging folders.
    static bool isArtifact(const QString &topName);
    /// Why the artifacts were moved in one by one instead of swapped in one step ("" when they
    /// were swapped): a run killed meanwhile could then leave old and new files mixed, which the
    /// person is told.
    const QString &inPlaceReason() const { return m_inPlaceReason; }
    /// How many files the last commit() linked unchanged instead of writing: for tests.
    int unchanged() const { return m_unchanged; }
    /// Removes the staging folders beside the output folder whose run is gone (killed). begin()
    /// does it; a run that finds the folder unchanged() writes nothing and does it too.
    void removeStale() const;

private:
    bool carryOver(const QString &from, const QString &to, int *budget) const;
    bool syncFolders(QString *error) const;
    bool writeStamp(const QByteArray &stamp, QString *error);
    bool commitInPlace(QStringList *written, QString *error);

    QString m_dir;     ///< the output folder, absolute
    QString m_parent;  ///< its parent
    QString m_prefix;  ///< ".<name>.rosarch-writing-": the staging folders' names begin so
    QString m_staging; ///< the fresh folder (beside m_dir, or inside it in place)
    bool m_inPlace = false;
    QString m_inPlaceReason;
    QStringList m_files;   ///< relative paths added, in order
    QStringList m_folders; ///< relative folders made in the staging folder
    int m_unchanged = 0;
};

} // namespace rosarch
