#pragma once

#include <QList>
#include <QObject>
#include <QString>

namespace rosarch {

/// A place a person went to in one panel of the window, named by stable keys (blueprint §5),
/// never by row: it is found again after a correction or a re-run reshapes the rows.
struct NavigationPlace
{
    enum class Panel
    {
        Nodes,    ///< the atomic node list: `key` is the row's stable key
        Launch,   ///< the launch tree: `key` is the row's stable key
        Diagram,  ///< the composed diagram: `key` is the composite's, `element` what is selected
        Source,   ///< the source pane: `key` is the file, relative to the workspace
        Findings, ///< the Log's findings: `key` is the finding's key
    };
    Panel panel = Panel::Nodes;
    QString key;
    /// In the diagram: the selected element as an instance key ("instance:…", with "|" and a
    /// port id for a port), a channel key ("topic:/x") or a diagram key named by name.
    QString element;
    /// The node list's and the launch tree's rows that followed it (their stable keys).
    QString nodeKey;
    QString launchKey;
    QString label; ///< what a person calls it ("navigator"), for the actions' tooltips
    // Where the source pane stood with it (its file, cursor line and first line shown).
    QString sourceFile;
    int sourceLine = -1;
    int sourceFirstLine = -1;

    /// The same element in the same panel (the source position may differ).
    bool samePlace(const NavigationPlace &other) const
    {
        return panel == other.panel && key == other.key && element == other.element;
    }
};

/// Back and forward over the places a person went to: visiting a place after going back
/// drops the places ahead, as in a browser. At most kCapacity places are kept.
class NavigationHistory : public QObject
{
    Q_OBJECT
public:
    static constexpr int kCapacity = 200;

    explicit NavigationHistory(QObject *parent = nullptr);

    /// Records `place` as the current one. The same place as the current one only updates its
    /// source position.
    void visit(const NavigationPlace &place);
    /// Updates the source position of the current place (before leaving it).
    void updateCurrent(const NavigationPlace &place);

    bool canGoBack() const { return m_index > 0; }
    bool canGoForward() const { return m_index >= 0 && m_index + 1 < m_places.size(); }
    /// Steps back (or forward) and returns the place to show; `nullptr` when there is none.
    const NavigationPlace *back();
    const NavigationPlace *forward();

    const NavigationPlace *current() const;
    QList<NavigationPlace> places() const { return m_places; }
    int currentIndex() const { return m_index; }
    void clear();

Q_SIGNALS:
    /// canGoBack() or canGoForward() may have changed.
    void changed();

private:
    QList<NavigationPlace> m_places;
    int m_index = -1;
};

} // namespace rosarch
