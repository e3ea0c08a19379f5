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
  rosarch recover &lt;workspace&gt; --out &lt;dir&gt; [--launch-arg name:=value]... [--launch-root &lt;file&gt;]
                                            run the stages headless and write the artifacts
  rosarch --help | --version

Artifacts written by recover: atomic_nodes.json, launch_dependencies.json, diagnostics.json,
acd/&lt;ClassName&gt;.puml
Exit codes: 0 ok, 1 analysis finished with errors reported, 2 usage error.
</source>
        <translation>Aufruf:
  rosarch [workspace]                       die GUI öffnen (standardmäßig mit dem Beispiel-Workspace)
  rosarch recover &lt;workspace&gt; --out &lt;dir&gt; [--launch-arg name:=value]... [--launch-root &lt;file&gt;]
                                            die Stufen ohne GUI ausführen und die Artefakte schreiben
  rosarch --help | --version

Von recover geschriebene Artefakte: atomic_nodes.json, launch_dependencies.json, diagnostics.json,
acd/&lt;ClassName&gt;.puml
Exit-Codes: 0 OK, 1 Analyse mit gemeldeten Fehlern abgeschlossen, 2 Aufruffehler.
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="50"/>
        <source>Recover the architecture of a ROS 2 workspace and write the artifacts.</source>
        <translation>Die Architektur eines ROS-2-Workspaces rekonstruieren und die Artefakte schreiben.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="55"/>
        <source>The workspace folder to analyse.</source>
        <translation>Der zu analysierende Workspace-Ordner.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="57"/>
        <source>Folder for the artifacts.</source>
        <translation>Ordner für die Artefakte.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="60"/>
        <source>Print only errors.</source>
        <translation>Nur Fehler ausgeben.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="62"/>
        <source>Set a launch argument (repeatable).</source>
        <translation>Ein Launch-Argument setzen (wiederholbar).</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="65"/>
        <source>Analyse only this launch file (relative to the workspace) as the root.</source>
        <translation>Nur dieses Launch-File (relativ zum Workspace) als Wurzel analysieren.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="82"/>
        <source>recover needs a workspace folder and --out &lt;dir&gt;.

</source>
        <translation>recover benötigt einen Workspace-Ordner und --out &lt;dir&gt;.

</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="88"/>
        <source>Not a folder: %1
</source>
        <translation>Kein Ordner: %1
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="97"/>
        <source>--launch-arg expects name:=value, got &apos;%1&apos;.
</source>
        <translation>--launch-arg erwartet name:=value, erhalten: „%1“.
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="133"/>
        <source>Recovered %1 node classes with %2 ports in %3 packages; %4 launch files, %5 launch-file instances, %6 node instances, %7 unresolved items; in %8 ms; %9 diagnostics (%10 errors).
Wrote %11 files to %12
</source>
        <translation>%1 Knotenklassen mit %2 Ports in %3 Paketen rekonstruiert; %4 Launch-Files, %5 Launch-File-Instanzen, %6 Knoteninstanzen, %7 unaufgelöste Elemente; in %8 ms; %9 Diagnosen (%10 Fehler).
%11 Dateien nach %12 geschrieben
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="178"/>
        <source>Unknown command: %1

</source>
        <translation>Unbekannter Befehl: %1

</translation>
    </message>
</context>
<context>
    <name>rosarch::DiagnosticModel</name>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="46"/>
        <source>Info</source>
        <translation>Info</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="48"/>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="50"/>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="82"/>
        <source>At %1</source>
        <translation>In %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="96"/>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="98"/>
        <source>Location</source>
        <translation>Ort</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="100"/>
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
    <name>rosarch::LaunchArgumentsDialog</name>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="33"/>
        <source>&amp;Remove</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="35"/>
        <source>Launch Arguments</source>
        <translation>Launch-Argumente</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="39"/>
        <source>Stage 2 reads the launch files as &lt;code&gt;ros2 launch&lt;/code&gt; would run them: choose the launch file to start from and give values to its arguments. Empty values use the default.</source>
        <translation>Stufe 2 liest die Launch-Files so, wie &lt;code&gt;ros2 launch&lt;/code&gt; sie ausführen würde: Wählen Sie das Launch-File, bei dem begonnen wird, und geben Sie seinen Argumenten Werte. Leere Werte verwenden den Standardwert.</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="46"/>
        <source>The launch file stage 2 starts from</source>
        <translation>Das Launch-File, bei dem Stufe 2 beginnt</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="52"/>
        <source>&amp;Root launch file:</source>
        <translation>&amp;Wurzel-Launch-File:</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="55"/>
        <source>Argument</source>
        <translation>Argument</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="55"/>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="55"/>
        <source>Default</source>
        <translation>Standardwert</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="55"/>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="55"/>
        <source>Declared in</source>
        <translation>Deklariert in</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="80"/>
        <source>&amp;Add Argument</source>
        <translation>Argument &amp;hinzufügen</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="81"/>
        <source>Give a value to an argument the list does not show</source>
        <translation>Einem Argument, das die Liste nicht zeigt, einen Wert geben</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="84"/>
        <source>Remove an argument you added</source>
        <translation>Ein von Ihnen hinzugefügtes Argument entfernen</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="86"/>
        <source>Use &amp;Defaults</source>
        <translation>&amp;Standardwerte verwenden</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="87"/>
        <source>Clear every value so that each argument uses its default</source>
        <translation>Alle Werte leeren, sodass jedes Argument seinen Standardwert verwendet</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="96"/>
        <source>Run Stage &amp;2</source>
        <translation>Stufe &amp;2 ausführen</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="123"/>
        <source>All top-level launch files</source>
        <translation>Alle Launch-Files der obersten Ebene</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="214"/>
        <source>The value stage 2 gives %1; leave empty for the default</source>
        <translation>Der Wert, den Stufe 2 für %1 verwendet; leer lassen für den Standardwert</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="224"/>
        <source>Not declared by a top-level launch file</source>
        <translation>Von keinem Launch-File der obersten Ebene deklariert</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="225"/>
        <source>Not declared by this launch file</source>
        <translation>Nicht von diesem Launch-File deklariert</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="231"/>
        <source>(none)</source>
        <translation>(keiner)</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="235"/>
        <source>%1 has no default: without a value the analysis continues with a guess.</source>
        <translation>%1 hat keinen Standardwert: Ohne Wert arbeitet die Analyse mit einer Annahme weiter.</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="261"/>
        <source>The arguments %1 declares are listed once stage 2 has run with it as the root: run it, then open this dialog again. Values you add here are used.</source>
        <translation>Die Argumente, die %1 deklariert, werden aufgeführt, sobald Stufe 2 mit dieser Datei als Wurzel gelaufen ist: Führen Sie Stufe 2 aus und öffnen Sie dann diesen Dialog erneut. Hier hinzugefügte Werte werden verwendet.</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="266"/>
        <source>No launch arguments are declared. Add one to give it a value.</source>
        <translation>Es sind keine Launch-Argumente deklariert. Fügen Sie eines hinzu, um ihm einen Wert zu geben.</translation>
    </message>
</context>
<context>
    <name>rosarch::LaunchTreeModel</name>
    <message>
        <location filename="../widgets/launchtreemodel.cpp" line="222"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodel.cpp" line="224"/>
        <source>Namespace</source>
        <translation>Namespace</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodel.cpp" line="226"/>
        <source>Package / executable</source>
        <translation>Paket / Executable</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodel.cpp" line="228"/>
        <source>Class</source>
        <translation>Klasse</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodel.cpp" line="230"/>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodel.cpp" line="247"/>
        <source>(unresolved include)</source>
        <translation>(unaufgelöstes Include)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodel.cpp" line="293"/>
        <source>namespace scope</source>
        <translation>Namespace-Bereich</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodel.cpp" line="322"/>
        <source>(not found)</source>
        <translation>(nicht gefunden)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodel.cpp" line="322"/>
        <source>(external)</source>
        <translation>(extern)</translation>
    </message>
</context>
<context>
    <name>rosarch::LaunchTreePanel</name>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="19"/>
        <source>&amp;Go to Class</source>
        <translation>Zur &amp;Klasse wechseln</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="23"/>
        <source>Filter by name, namespace, class or executable</source>
        <translation>Nach Name, Namespace, Klasse oder Executable filtern</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="25"/>
        <source>Shows the launch files, namespaces and node instances whose name, namespace, class or executable contains this text. Esc clears the filter.</source>
        <translation>Zeigt die Launch-Files, Namespaces und Knoteninstanzen, deren Name, Namespace, Klasse oder Executable diesen Text enthält. Esc setzt den Filter zurück.</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="43"/>
        <source>Select the atomic node class this node instance runs</source>
        <translation>Die atomare Knotenklasse auswählen, die diese Knoteninstanz ausführt</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="51"/>
        <source>&amp;Expand All</source>
        <translation>Alle &amp;ausklappen</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="53"/>
        <source>&amp;Collapse All</source>
        <translation>Alle &amp;einklappen</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="76"/>
        <source>No launch files analysed yet.</source>
        <translation>Noch keine Launch-Files analysiert.</translation>
    </message>
</context>
<context>
    <name>rosarch::LaunchTreeText</name>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="57"/>
        <source>Substitution</source>
        <translation>Substitution</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="59"/>
        <source>Condition</source>
        <translation>Bedingung</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="61"/>
        <source>Include</source>
        <translation>Include</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="63"/>
        <source>Opaque function</source>
        <translation>Opake Funktion</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="65"/>
        <source>Argument</source>
        <translation>Argument</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="66"/>
        <source>Expression</source>
        <translation>Ausdruck</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="90"/>
        <location filename="../widgets/launchtreetext.cpp" line="112"/>
        <source>if: %1</source>
        <translation>wenn: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="92"/>
        <source>container of 1 component</source>
        <translation>Container mit 1 Komponente</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="93"/>
        <source>container of %1 components</source>
        <translation>Container mit %1 Komponenten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="95"/>
        <source>lifecycle</source>
        <translation>Lifecycle</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="97"/>
        <source>remap: %1</source>
        <translation>Remap: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="99"/>
        <source>param: %1</source>
        <translation>Param: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="101"/>
        <source>1 unresolved</source>
        <translation>1 unaufgelöst</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="102"/>
        <source>%1 unresolved</source>
        <translation>%1 unaufgelöst</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="110"/>
        <source>external</source>
        <translation>extern</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="116"/>
        <source>1 node</source>
        <translation>1 Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="117"/>
        <source>%1 nodes</source>
        <translation>%1 Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="120"/>
        <source>1 include</source>
        <translation>1 Include</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="121"/>
        <source>%1 includes</source>
        <translation>%1 Includes</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="130"/>
        <source>unresolved (%1)</source>
        <translation>unaufgelöst (%1)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="131"/>
        <source>unresolved (%1) · guess: %2</source>
        <translation>unaufgelöst (%1) · Annahme: %2</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="137"/>
        <source>Composable node</source>
        <translation>Komponierbarer Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="138"/>
        <source>Lifecycle node</source>
        <translation>Lifecycle-Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="139"/>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="143"/>
        <location filename="../widgets/launchtreetext.cpp" line="202"/>
        <source>Package: %1</source>
        <translation>Paket: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="146"/>
        <source>Plugin: %1</source>
        <translation>Plugin: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="146"/>
        <source>Executable: %1</source>
        <translation>Executable: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="149"/>
        <source>Class: %1</source>
        <translation>Klasse: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="154"/>
        <source>Class: not found in the workspace</source>
        <translation>Klasse: nicht im Workspace gefunden</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="155"/>
        <source>Class: not analysed; package %1 is not in the workspace</source>
        <translation>Klasse: nicht analysiert; Paket %1 liegt nicht im Workspace</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="159"/>
        <source>Loaded into container: %1</source>
        <translation>Geladen in Container: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="162"/>
        <location filename="../widgets/launchtreetext.cpp" line="205"/>
        <source>Condition: %1 (true)</source>
        <translation>Bedingung: %1 (wahr)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="163"/>
        <source>Condition: %1 (&lt;b&gt;false&lt;/b&gt;: not started)</source>
        <translation>Bedingung: %1 (&lt;b&gt;falsch&lt;/b&gt;: nicht gestartet)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="165"/>
        <source>&lt;b&gt;Inactive:&lt;/b&gt; the launch file that declares it is not included</source>
        <translation>&lt;b&gt;Inaktiv:&lt;/b&gt; Das Launch-File, das ihn deklariert, wird nicht eingebunden</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="170"/>
        <source>Remappings:</source>
        <translation>Remaps:</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="176"/>
        <source>file %1</source>
        <translation>Datei %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="178"/>
        <source>Parameters:</source>
        <translation>Parameter:</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="181"/>
        <location filename="../widgets/launchtreetext.cpp" line="216"/>
        <source>Not resolved statically:</source>
        <translation>Nicht statisch aufgelöst:</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="183"/>
        <source>Declared at %1</source>
        <translation>Deklariert in %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="191"/>
        <source>Launch file</source>
        <translation>Launch-File</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="192"/>
        <source>External include</source>
        <translation>Externes Include</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="193"/>
        <source>Included launch file</source>
        <translation>Eingebundenes Launch-File</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="197"/>
        <source>File: %1</source>
        <translation>Datei: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="199"/>
        <source>Package %1 is not in the workspace; its nodes are not analysed.</source>
        <translation>Paket %1 liegt nicht im Workspace; seine Knoten werden nicht analysiert.</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="206"/>
        <source>Condition: %1 (&lt;b&gt;false&lt;/b&gt;: not included)</source>
        <translation>Bedingung: %1 (&lt;b&gt;falsch&lt;/b&gt;: nicht eingebunden)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="208"/>
        <source>&lt;b&gt;Inactive:&lt;/b&gt; the launch file that includes it is not included</source>
        <translation>&lt;b&gt;Inaktiv:&lt;/b&gt; Das Launch-File, das es einbindet, wird nicht eingebunden</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="213"/>
        <source>Launch arguments:</source>
        <translation>Launch-Argumente:</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="218"/>
        <location filename="../widgets/launchtreetext.cpp" line="243"/>
        <source>At %1</source>
        <translation>In %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="218"/>
        <source>Included at %1</source>
        <translation>Eingebunden in %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="226"/>
        <source>&lt;b&gt;Namespace&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Namespace&lt;/b&gt; %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="227"/>
        <source>Pushed in %1</source>
        <translation>Gesetzt in %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="229"/>
        <source>1 instance inside this scope</source>
        <translation>1 Instanz in diesem Bereich</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="230"/>
        <source>%1 instances inside this scope</source>
        <translation>%1 Instanzen in diesem Bereich</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="237"/>
        <source>&lt;b&gt;Not resolved statically:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Nicht statisch aufgelöst:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="241"/>
        <source>The analysis continued with: %1</source>
        <translation>Die Analyse wurde fortgesetzt mit: %1</translation>
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
        <location filename="../app/mainwindow.cpp" line="56"/>
        <source>rosarch</source>
        <translation>rosarch</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="117"/>
        <source>Atomic nodes</source>
        <translation>Atomare Knoten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="118"/>
        <source>Launch tree</source>
        <translation>Launch-Baum</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="119"/>
        <source>Source</source>
        <translation>Quelltext</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="120"/>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="163"/>
        <source>&amp;Open Workspace…</source>
        <translation>Workspace ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="165"/>
        <source>Open a ROS 2 workspace folder and recover its architecture</source>
        <translation>Einen ROS-2-Workspace-Ordner öffnen und seine Architektur rekonstruieren</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="168"/>
        <source>&amp;Export Artifacts…</source>
        <translation>Artefakte &amp;exportieren…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="169"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="175"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="180"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="182"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="185"/>
        <source>&amp;Find…</source>
        <translation>&amp;Suchen…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="201"/>
        <source>&amp;Next Diagnostic</source>
        <translation>&amp;Nächste Diagnose</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="207"/>
        <source>&amp;Previous Diagnostic</source>
        <translation>&amp;Vorherige Diagnose</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="171"/>
        <source>Write atomic_nodes.json, launch_dependencies.json, diagnostics.json and one PlantUML diagram per node</source>
        <translation>atomic_nodes.json, launch_dependencies.json, diagnostics.json und ein PlantUML-Diagramm pro Knoten schreiben</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="187"/>
        <source>Filter the node tree, or the launch tree when it has the focus, by name</source>
        <translation>Den Knotenbaum – oder den Launch-Baum, wenn er den Fokus hat – nach Name filtern</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="214"/>
        <source>&amp;Run All Stages</source>
        <translation>Alle Stufen aus&amp;führen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="215"/>
        <source>Run all</source>
        <translation>Alle ausführen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="217"/>
        <source>Recover the atomic nodes and the launch tree of the workspace (F5)</source>
        <translation>Die atomaren Knoten und den Launch-Baum des Workspaces rekonstruieren (F5)</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="219"/>
        <source>Stage 1 finds node classes, their ports and executables; stage 2 reads the launch files</source>
        <translation>Stufe 1 findet Knotenklassen, ihre Ports und Executables; Stufe 2 liest die Launch-Files</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="223"/>
        <source>Run Stage &amp;2: Launch Files</source>
        <translation>Stufe &amp;2 ausführen: Launch-Files</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="224"/>
        <source>Stage 2</source>
        <translation>Stufe 2</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="226"/>
        <source>Read the launch files again against the current atomic nodes, with the chosen launch arguments (F6)</source>
        <translation>Die Launch-Files mit den gewählten Launch-Argumenten erneut lesen und mit den aktuellen atomaren Knoten abgleichen (F6)</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="228"/>
        <source>Re-run stage 2 only: launch files, includes, namespaces and node instances</source>
        <translation>Nur Stufe 2 erneut ausführen: Launch-Files, Includes, Namespaces und Knoteninstanzen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="232"/>
        <source>Launch &amp;Arguments…</source>
        <translation>&amp;Launch-Argumente…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="233"/>
        <source>Arguments</source>
        <translation>Argumente</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="234"/>
        <source>Ctrl+Shift+A</source>
        <translation>Ctrl+Shift+A</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="236"/>
        <source>Choose the root launch file and the launch argument values for stage 2</source>
        <translation>Das Wurzel-Launch-File und die Werte der Launch-Argumente für Stufe 2 wählen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="240"/>
        <source>&amp;Cancel Stage</source>
        <translation>Stufe &amp;abbrechen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="241"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="243"/>
        <source>Stop the running stage and keep the previous result (Esc)</source>
        <translation>Die laufende Stufe anhalten und das vorherige Ergebnis behalten (Esc)</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="246"/>
        <source>&amp;Reset Layout</source>
        <translation>Layout &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="249"/>
        <source>&amp;About rosarch</source>
        <translation>&amp;Über rosarch</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="255"/>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="262"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="264"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="271"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="280"/>
        <source>Main</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="291"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="294"/>
        <source>&amp;Toolbar</source>
        <translation>&amp;Werkzeugleiste</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="299"/>
        <source>&amp;Stages</source>
        <translation>&amp;Stufen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="307"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="382"/>
        <source>Open ROS 2 Workspace</source>
        <translation>ROS-2-Workspace öffnen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="393"/>
        <source>Cannot open workspace</source>
        <translation>Workspace kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="394"/>
        <source>The folder “%1” does not exist or is not a folder.

Choose a ROS 2 workspace (a folder containing packages with a package.xml) with File → Open Workspace, or drop one onto the window.</source>
        <translation>Der Ordner „%1“ existiert nicht oder ist kein Ordner.

Wählen Sie über Datei → Workspace öffnen einen ROS-2-Workspace (einen Ordner mit Paketen, die eine package.xml enthalten) aus, oder ziehen Sie einen Workspace auf das Fenster.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="408"/>
        <source>%1 — rosarch</source>
        <translation>%1 — rosarch</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="451"/>
        <source>No recent workspaces</source>
        <translation>Keine zuletzt geöffneten Workspaces</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="456"/>
        <source>&amp;%1 %2 — %3</source>
        <translation>&amp;%1 %2 — %3</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="464"/>
        <source>&amp;Clear Menu</source>
        <translation>Menü &amp;leeren</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="475"/>
        <source>Export Artifacts To</source>
        <translation>Artefakte exportieren nach</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="488"/>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="489"/>
        <source>The artifacts could not be written to “%1”:
%2

Choose a folder you can write to, or free some space, and export again.</source>
        <translation>Die Artefakte konnten nicht nach „%1“ geschrieben werden:
%2

Wählen Sie einen Ordner, in den Sie schreiben dürfen, oder geben Sie Speicherplatz frei, und exportieren Sie erneut.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="492"/>
        <source>Export to %1 failed: %2</source>
        <translation>Export nach %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="495"/>
        <source>Exported 1 file to %1</source>
        <translation>1 Datei nach %1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="496"/>
        <source>Exported %1 files to %2</source>
        <translation>%1 Dateien nach %2 exportiert</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="528"/>
        <source>1 package</source>
        <translation>1 Paket</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="528"/>
        <source>%1 packages</source>
        <translation>%1 Pakete</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="529"/>
        <source>1 node</source>
        <translation>1 Knoten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="529"/>
        <source>%1 nodes</source>
        <translation>%1 Knoten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="530"/>
        <source>1 port</source>
        <translation>1 Port</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="530"/>
        <source>%1 ports</source>
        <translation>%1 Ports</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="531"/>
        <source>1 launch file</source>
        <translation>1 Launch-File</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="531"/>
        <source>%1 launch files</source>
        <translation>%1 Launch-Files</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="532"/>
        <source>1 instance</source>
        <translation>1 Instanz</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="532"/>
        <source>%1 instances</source>
        <translation>%1 Instanzen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="533"/>
        <source>1 unresolved</source>
        <translation>1 unaufgelöst</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="533"/>
        <source>%1 unresolved</source>
        <translation>%1 unaufgelöst</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="534"/>
        <source>1 diagnostic</source>
        <translation>1 Diagnose</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="534"/>
        <source>%1 diagnostics</source>
        <translation>%1 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="536"/>
        <source>Stage 1: packages, atomic node classes and their ports.
Stage 2: launch files found, node instances they start and expressions that could not be resolved statically.</source>
        <translation>Stufe 1: Pakete, atomare Knotenklassen und ihre Ports.
Stufe 2: gefundene Launch-Files, die von ihnen gestarteten Knoteninstanzen und Ausdrücke, die nicht statisch aufgelöst werden konnten.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="550"/>
        <source>Open a ROS 2 workspace (File → Open Workspace) to see its launch tree.</source>
        <translation>Öffnen Sie einen ROS-2-Workspace (Datei → Workspace öffnen), um seinen Launch-Baum zu sehen.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="552"/>
        <source>Reading the launch files…</source>
        <translation>Die Launch-Files werden gelesen…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="555"/>
        <source>No launch files found in this workspace.

Stage 2 reads *.launch.py, *.launch.xml and *.launch.yaml files and any file holding a launch description.</source>
        <translation>In diesem Workspace wurden keine Launch-Files gefunden.

Stufe 2 liest *.launch.py-, *.launch.xml- und *.launch.yaml-Dateien sowie jede Datei, die eine Launch-Beschreibung enthält.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="560"/>
        <source>No launch file was analysed as a root.

Choose one in Stages → Launch Arguments…</source>
        <translation>Es wurde kein Launch-File als Wurzel analysiert.

Wählen Sie eines unter Stufen → Launch-Argumente…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="590"/>
        <source>[%1/%2] %3</source>
        <translation>[%1/%2] %3</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="127"/>
        <source>Cannot show %1</source>
        <translation>%1 kann nicht angezeigt werden</translation>
    </message>
</context>
<context>
    <name>rosarch::SourceView</name>
    <message>
        <location filename="../widgets/sourceview.cpp" line="165"/>
        <source>Cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="167"/>
        <source>%1 is too large to show (%2 MB)</source>
        <translation>%1 ist zu groß für die Anzeige (%2 MB)</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="344"/>
        <source>Select a node, port, launch item or diagnostic to see its source.</source>
        <translation>Wählen Sie einen Knoten, einen Port, ein Launch-Element oder eine Diagnose aus, um den Quelltext zu sehen.</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="354"/>
        <source>lines %1–%2</source>
        <translation>Zeilen %1–%2</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="356"/>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
</context>
<context>
    <name>rosarch::StageController</name>
    <message>
        <location filename="../app/stagecontroller.cpp" line="99"/>
        <source>Stages 1–2 (atomic nodes, launch files) started on %1</source>
        <translation>Stufen 1–2 (atomare Knoten, Launch-Files) gestartet für %1</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="100"/>
        <source>Recovering atomic nodes and launch files…</source>
        <translation>Atomare Knoten und Launch-Files werden rekonstruiert…</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="102"/>
        <source>Stage 2 (launch files) started on %1</source>
        <translation>Stufe 2 (Launch-Files) gestartet für %1</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="103"/>
        <source>Reading launch files…</source>
        <translation>Launch-Files werden gelesen…</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="118"/>
        <source>Stages 1–2 finished in %1 s: %2 nodes, %3 ports, %4 launch files, %5 node instances, %6 diagnostics</source>
        <translation>Stufen 1–2 in %1 s abgeschlossen: %2 Knoten, %3 Ports, %4 Launch-Files, %5 Knoteninstanzen, %6 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="132"/>
        <source>Stage 2 finished in %1 s: %2 launch files, %3 launch-file instances, %4 node instances, %5 diagnostics</source>
        <translation>Stufe 2 in %1 s abgeschlossen: %2 Launch-Files, %3 Launch-File-Instanzen, %4 Knoteninstanzen, %5 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="149"/>
        <source>Stages 1–2</source>
        <translation>Stufen 1–2</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="149"/>
        <source>Stage 2</source>
        <translation>Stufe 2</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="150"/>
        <source>%1 canceled; the previous result is kept.</source>
        <translation>%1 abgebrochen; das vorherige Ergebnis bleibt erhalten.</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="151"/>
        <source>%1 canceled</source>
        <translation>%1 abgebrochen</translation>
    </message>
</context>
<context>
    <name>rosarch::StageRunner</name>
    <message>
        <location filename="../app/stagerunner.cpp" line="19"/>
        <source>Stage %1 stopped with an internal error: %2</source>
        <translation>Stufe %1 wurde wegen eines internen Fehlers abgebrochen: %2</translation>
    </message>
</context>
</TS>
