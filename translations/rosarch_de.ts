<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>rosarch::AboutDialog</name>
    <message>
        <location filename="../app/aboutdialog.cpp" line="16"/>
        <source>About rosarch</source>
        <translation>Über rosarch</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="28"/>
        <source>Recovers the architecture of a ROS 2 workspace from its source code, build files and launch files, without building or running it.</source>
        <translation>Rekonstruiert die Architektur eines ROS-2-Workspaces aus Quellcode, Build-Dateien und Launch-Files, ohne ihn zu bauen oder auszuführen.</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="31"/>
        <source>Built with</source>
        <translation>Erstellt mit</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="50"/>
        <source>rosarch</source>
        <translation>rosarch</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="51"/>
        <source>Qt</source>
        <translation>Qt</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="52"/>
        <source>%1 (built with %2)</source>
        <translation>%1 (erstellt mit %2)</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="54"/>
        <source>tree-sitter language ABI</source>
        <translation>tree-sitter-Sprach-ABI</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="55"/>
        <source>QScintilla</source>
        <translation>QScintilla</translation>
    </message>
</context>
<context>
    <name>rosarch::AtomicNodeModel</name>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="328"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="330"/>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="332"/>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="334"/>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="347"/>
        <source>(outside any package)</source>
        <translation>(keinem Paket zugeordnet)</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="352"/>
        <source>1 node</source>
        <translation>1 Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="352"/>
        <source>%1 nodes</source>
        <translation>%1 Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="386"/>
        <source>procedural node</source>
        <translation>prozeduraler Knoten</translation>
    </message>
</context>
<context>
    <name>rosarch::AtomicNodePanel</name>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="19"/>
        <source>Filter by name or type (Ctrl+F)</source>
        <translation>Nach Name oder Typ filtern (Ctrl+F)</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="21"/>
        <source>Shows the packages, nodes and ports whose name or type contains this text. Esc clears the filter.</source>
        <translation>Zeigt die Pakete, Knoten und Ports, deren Name oder Typ diesen Text enthält. Esc setzt den Filter zurück.</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="37"/>
        <source>Edit &amp;Description</source>
        <translation>&amp;Beschreibung bearbeiten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="40"/>
        <source>Describe the node&apos;s responsibility (undoable)</source>
        <translation>Die Aufgabe des Knotens beschreiben (kann rückgängig gemacht werden)</translation>
    </message>
</context>
<context>
    <name>rosarch::AtomicNodeText</name>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="24"/>
        <source>Publisher</source>
        <translation>Publisher</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="26"/>
        <source>Subscriber</source>
        <translation>Subscriber</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="28"/>
        <source>Service server</source>
        <translation>Service-Server</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="30"/>
        <source>Service client</source>
        <translation>Service-Client</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="32"/>
        <source>Action server</source>
        <translation>Action-Server</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="34"/>
        <source>Action client</source>
        <translation>Action-Client</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="43"/>
        <source>node: %1</source>
        <translation>Knoten: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="45"/>
        <source>plugin: %1</source>
        <translation>Plugin: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="45"/>
        <source>exec: %1</source>
        <translation>exec: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="47"/>
        <location filename="../widgets/atomicnodetext.cpp" line="117"/>
        <source>Python</source>
        <translation>Python</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="47"/>
        <location filename="../widgets/atomicnodetext.cpp" line="117"/>
        <source>C++</source>
        <translation>C++</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="49"/>
        <source>lifecycle</source>
        <translation>Lifecycle</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="57"/>
        <source>callback: %1</source>
        <translation>Callback: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="62"/>
        <source>member</source>
        <translation>Member</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="65"/>
        <source>local</source>
        <translation>lokal</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="68"/>
        <source>param: %1</source>
        <translation>Param: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="71"/>
        <source>unresolved: %1</source>
        <translation>unaufgelöst: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="75"/>
        <source>guard: %1</source>
        <translation>Bedingung: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="77"/>
        <source>via: %1</source>
        <translation>über: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="79"/>
        <source>inherited</source>
        <translation>geerbt</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="85"/>
        <source>&lt;b&gt;ROS 2 package&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;ROS-2-Paket&lt;/b&gt; %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="88"/>
        <source>Named by node sources only; no package.xml found.</source>
        <translation>Nur durch Knoten-Quelldateien benannt; keine package.xml gefunden.</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="90"/>
        <source>Build type: %1</source>
        <translation>Build-Typ: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="92"/>
        <source>1 atomic node</source>
        <translation>1 atomarer Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="92"/>
        <source>%1 atomic nodes</source>
        <translation>%1 atomare Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="94"/>
        <source>Declared in %1</source>
        <translation>Deklariert in %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="100"/>
        <source>Lifecycle node class</source>
        <translation>Lifecycle-Knotenklasse</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="101"/>
        <source>Procedurally built node</source>
        <translation>Prozedural aufgebauter Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="102"/>
        <source>Atomic ROS node class</source>
        <translation>Atomare ROS-Knotenklasse</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="108"/>
        <source>Node name in code: %1</source>
        <translation>Knotenname im Code: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="110"/>
        <source>Derives from: %1</source>
        <translation>Abgeleitet von: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="113"/>
        <source>Started by executable: %1</source>
        <translation>Gestartet durch Executable: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="115"/>
        <source>Component plugin: %1</source>
        <translation>Komponenten-Plugin: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="116"/>
        <source>Compile type: %1</source>
        <translation>Kompilierungsart: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="118"/>
        <source>1 port</source>
        <translation>1 Port</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="118"/>
        <source>%1 ports</source>
        <translation>%1 Ports</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="120"/>
        <source>Description: %1</source>
        <translation>Beschreibung: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="122"/>
        <source>Defined at %1</source>
        <translation>Definiert in %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="132"/>
        <source>Of node %1</source>
        <translation>Gehört zu Knoten %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="134"/>
        <source>Interface type: %1</source>
        <translation>Interface-Typ: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="136"/>
        <source>Callback: %1</source>
        <translation>Callback: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="139"/>
        <source>Name written as a literal</source>
        <translation>Name als Literal angegeben</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="142"/>
        <source>Name taken from a member variable</source>
        <translation>Name aus einer Membervariable übernommen</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="145"/>
        <source>Name taken from a local variable</source>
        <translation>Name aus einer lokalen Variable übernommen</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="148"/>
        <source>Name is the default of parameter &apos;%1&apos;</source>
        <translation>Name ist der Standardwert des Parameters „%1“</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="151"/>
        <source>Name could not be resolved statically: %1</source>
        <translation>Name konnte nicht statisch aufgelöst werden: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="155"/>
        <source>Exists only if: %1</source>
        <translation>Existiert nur, wenn: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="157"/>
        <source>Created through: %1</source>
        <translation>Erzeugt über: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="159"/>
        <source>Declared in a base class</source>
        <translation>In einer Basisklasse deklariert</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="161"/>
        <source>Created at %1</source>
        <translation>Erzeugt in %1</translation>
    </message>
</context>
<context>
    <name>rosarch::CommandLine</name>
    <message>
        <location filename="../app/commandline.cpp" line="22"/>
        <source>Usage:
  rosarch [workspace]                       open the GUI (on the example workspace by default)
  rosarch recover &lt;workspace&gt; --out &lt;dir&gt;   run the stages headless and write the artifacts
  rosarch --help | --version

Artifacts written by recover: atomic_nodes.json, diagnostics.json, acd/&lt;ClassName&gt;.puml
Exit codes: 0 ok, 1 analysis finished with errors reported, 2 usage error.
</source>
        <translation>Aufruf:
  rosarch [workspace]                       öffnet die GUI (standardmäßig mit dem Beispiel-Workspace)
  rosarch recover &lt;workspace&gt; --out &lt;dir&gt;   führt die Stufen ohne GUI aus und schreibt die Artefakte
  rosarch --help | --version

Von recover geschriebene Artefakte: atomic_nodes.json, diagnostics.json, acd/&lt;Klassenname&gt;.puml
Exit-Codes: 0 OK, 1 Analyse mit gemeldeten Fehlern beendet, 2 Aufruffehler.
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="38"/>
        <source>Recover the architecture of a ROS 2 workspace and write the artifacts.</source>
        <translation>Die Architektur eines ROS-2-Workspaces rekonstruieren und die Artefakte schreiben.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="43"/>
        <source>The workspace folder to analyse.</source>
        <translation>Der zu analysierende Workspace-Ordner.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="45"/>
        <source>Folder for the artifacts.</source>
        <translation>Ordner für die Artefakte.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="48"/>
        <source>Print only errors.</source>
        <translation>Nur Fehler ausgeben.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="61"/>
        <source>recover needs a workspace folder and --out &lt;dir&gt;.

</source>
        <translation>recover benötigt einen Workspace-Ordner und --out &lt;dir&gt;.

</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="67"/>
        <source>Not a folder: %1
</source>
        <translation>Kein Ordner: %1
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="98"/>
        <source>Recovered %1 node classes with %2 ports in %3 packages in %4 ms; %5 diagnostics (%6 errors).
Wrote %7 files to %8
</source>
        <translation>%1 Knotenklassen mit %2 Ports in %3 Paketen in %4 ms rekonstruiert; %5 Diagnosen (%6 Fehler).
%7 Dateien nach %8 geschrieben
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="140"/>
        <source>Unknown command: %1

</source>
        <translation>Unbekannter Befehl: %1

</translation>
    </message>
</context>
<context>
    <name>rosarch::DiagnosticModel</name>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="36"/>
        <source>Info</source>
        <translation>Info</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="38"/>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="40"/>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="72"/>
        <source>At %1</source>
        <translation>In %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="86"/>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="88"/>
        <source>Location</source>
        <translation>Ort</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="90"/>
        <source>Code</source>
        <translation>Code</translation>
    </message>
</context>
<context>
    <name>rosarch::Document</name>
    <message>
        <location filename="../document/setnodedescriptioncommand.cpp" line="13"/>
        <source>Edit description</source>
        <translation>Beschreibung bearbeiten</translation>
    </message>
</context>
<context>
    <name>rosarch::LogView</name>
    <message>
        <location filename="../widgets/logview.cpp" line="32"/>
        <source>Progress and messages of stage runs appear here.</source>
        <translation>Hier erscheinen Fortschritt und Meldungen der Stufenausführungen.</translation>
    </message>
</context>
<context>
    <name>rosarch::MainWindow</name>
    <message>
        <location filename="../app/mainwindow.cpp" line="50"/>
        <source>rosarch</source>
        <translation>rosarch</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="99"/>
        <source>Atomic nodes</source>
        <translation>Atomare Knoten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="100"/>
        <source>Source</source>
        <translation>Quelltext</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="101"/>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="133"/>
        <source>&amp;Open Workspace…</source>
        <translation>Workspace ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="135"/>
        <source>Open a ROS 2 workspace folder and recover its architecture</source>
        <translation>Einen ROS-2-Workspace-Ordner öffnen und seine Architektur rekonstruieren</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="138"/>
        <source>&amp;Export Artifacts…</source>
        <translation>Artefakte &amp;exportieren…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="139"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="141"/>
        <source>Write atomic_nodes.json, diagnostics.json and one PlantUML diagram per node</source>
        <translation>atomic_nodes.json, diagnostics.json und ein PlantUML-Diagramm pro Knoten schreiben</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="144"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="149"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="151"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="154"/>
        <source>&amp;Find…</source>
        <translation>&amp;Suchen…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="156"/>
        <source>Filter the node tree by name or type</source>
        <translation>Den Knotenbaum nach Name oder Typ filtern</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="163"/>
        <source>&amp;Next Diagnostic</source>
        <translation>&amp;Nächste Diagnose</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="169"/>
        <source>&amp;Previous Diagnostic</source>
        <translation>&amp;Vorherige Diagnose</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="176"/>
        <source>Run Stage &amp;1: Atomic Nodes</source>
        <translation>Stufe &amp;1 ausführen: Atomare Knoten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="177"/>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="179"/>
        <source>Recover the atomic nodes of the workspace (F5)</source>
        <translation>Die atomaren Knoten des Workspaces rekonstruieren (F5)</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="180"/>
        <source>Find node classes, their ports and their executables</source>
        <translation>Knotenklassen, ihre Ports und ihre Executables finden</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="183"/>
        <source>&amp;Cancel Stage</source>
        <translation>Stufe &amp;abbrechen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="184"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="186"/>
        <source>Stop the running stage and keep the previous result (Esc)</source>
        <translation>Die laufende Stufe anhalten und das vorherige Ergebnis behalten (Esc)</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="189"/>
        <source>&amp;Reset Layout</source>
        <translation>Layout &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="192"/>
        <source>&amp;About rosarch</source>
        <translation>&amp;Über rosarch</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="198"/>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="205"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="207"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="214"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="223"/>
        <source>Main</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="232"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="235"/>
        <source>&amp;Toolbar</source>
        <translation>&amp;Werkzeugleiste</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="240"/>
        <source>&amp;Stages</source>
        <translation>&amp;Stufen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="244"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="319"/>
        <source>Open ROS 2 Workspace</source>
        <translation>ROS-2-Workspace öffnen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="330"/>
        <source>Cannot open workspace</source>
        <translation>Workspace kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="331"/>
        <source>The folder “%1” does not exist or is not a folder.

Choose a ROS 2 workspace (a folder containing packages with a package.xml) with File → Open Workspace, or drop one onto the window.</source>
        <translation>Der Ordner „%1“ existiert nicht oder ist kein Ordner.

Wählen Sie über Datei → Workspace öffnen einen ROS-2-Workspace (einen Ordner mit Paketen, die eine package.xml enthalten) aus, oder ziehen Sie einen Workspace auf das Fenster.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="352"/>
        <source>%1 — rosarch</source>
        <translation>%1 — rosarch</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="376"/>
        <source>No recent workspaces</source>
        <translation>Keine zuletzt geöffneten Workspaces</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="381"/>
        <source>&amp;%1 %2 — %3</source>
        <translation>&amp;%1 %2 — %3</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="389"/>
        <source>&amp;Clear Menu</source>
        <translation>Menü &amp;leeren</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="400"/>
        <source>Export Artifacts To</source>
        <translation>Artefakte exportieren nach</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="412"/>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="413"/>
        <source>The artifacts could not be written to “%1”:
%2

Choose a folder you can write to, or free some space, and export again.</source>
        <translation>Die Artefakte konnten nicht nach „%1“ geschrieben werden:
%2

Wählen Sie einen Ordner, in den Sie schreiben dürfen, oder geben Sie Speicherplatz frei, und exportieren Sie erneut.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="416"/>
        <source>Export to %1 failed: %2</source>
        <translation>Export nach %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="419"/>
        <source>Exported 1 file to %1</source>
        <translation>1 Datei nach %1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="420"/>
        <source>Exported %1 files to %2</source>
        <translation>%1 Dateien nach %2 exportiert</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="445"/>
        <source>1 package</source>
        <translation>1 Paket</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="445"/>
        <source>%1 packages</source>
        <translation>%1 Pakete</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="446"/>
        <source>1 node</source>
        <translation>1 Knoten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="446"/>
        <source>%1 nodes</source>
        <translation>%1 Knoten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="447"/>
        <source>1 port</source>
        <translation>1 Port</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="447"/>
        <source>%1 ports</source>
        <translation>%1 Ports</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="448"/>
        <source>1 diagnostic</source>
        <translation>1 Diagnose</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="448"/>
        <source>%1 diagnostics</source>
        <translation>%1 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="468"/>
        <source>Stage 1 (atomic nodes) started on %1</source>
        <translation>Stufe 1 (atomare Knoten) für %1 gestartet</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="469"/>
        <source>Recovering atomic nodes…</source>
        <translation>Atomare Knoten werden rekonstruiert…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="483"/>
        <source>[%1/%2] %3</source>
        <translation>[%1/%2] %3</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="502"/>
        <source>Stage 1 finished in %1 s: %2 nodes, %3 ports, %4 diagnostics</source>
        <translation>Stufe 1 in %1 s abgeschlossen: %2 Knoten, %3 Ports, %4 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="518"/>
        <source>Stage 1 canceled; the previous result is kept.</source>
        <translation>Stufe 1 abgebrochen; das vorherige Ergebnis bleibt erhalten.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="519"/>
        <source>Stage 1 canceled</source>
        <translation>Stufe 1 abgebrochen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="542"/>
        <source>Cannot show %1</source>
        <translation>%1 kann nicht angezeigt werden</translation>
    </message>
</context>
<context>
    <name>rosarch::SourceView</name>
    <message>
        <location filename="../widgets/sourceview.cpp" line="162"/>
        <source>Cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="164"/>
        <source>%1 is too large to show (%2 MB)</source>
        <translation>%1 ist zu groß für die Anzeige (%2 MB)</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="339"/>
        <source>Select a node, port or diagnostic to see its source.</source>
        <translation>Wählen Sie einen Knoten, einen Port oder eine Diagnose aus, um den zugehörigen Quelltext zu sehen.</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="349"/>
        <source>lines %1–%2</source>
        <translation>Zeilen %1–%2</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="351"/>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
</context>
<context>
    <name>rosarch::StageRunner</name>
    <message>
        <location filename="../app/stagerunner.cpp" line="85"/>
        <source>Stage 1 stopped with an internal error: %1</source>
        <translation>Stufe 1 wegen eines internen Fehlers angehalten: %1</translation>
    </message>
</context>
</TS>
