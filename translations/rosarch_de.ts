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
        <location filename="../widgets/atomicnodepanel.cpp" line="15"/>
        <source>Filter by name or type (Ctrl+F)</source>
        <translation>Nach Name oder Typ filtern (Ctrl+F)</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="16"/>
        <source>Shows the packages, nodes and ports whose name or type contains this text. Esc clears the filter.</source>
        <translation>Zeigt die Pakete, Knoten und Ports, deren Name oder Typ diesen Text enthält. Esc setzt den Filter zurück.</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="22"/>
        <source>Edit &amp;Description</source>
        <translation>&amp;Beschreibung bearbeiten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="25"/>
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
        <location filename="../app/commandline.cpp" line="24"/>
        <source>Usage:
  rosarch [workspace]                       open the GUI (on the example workspace by default)
  rosarch recover &lt;workspace&gt; --out &lt;dir&gt; [--launch-arg name:=value]... [--launch-root &lt;file&gt;]
                                            run the stages headless and write the artifacts
  rosarch eval --reference &lt;dir|file&gt; --recovered &lt;dir|file&gt; [--level acd|ccd] [--json]
                                            score recovered PlantUML diagrams against a reference
  rosarch suggest &lt;workspace&gt; --out &lt;dir&gt; [--llm-endpoint URL] [--llm-model NAME] [--llm-timeout S]
                                            write checked suggestions to suggestions.json
                                            (deterministic only without an endpoint)
  rosarch --help | --version

Artifacts written by recover: atomic_nodes.json, launch_dependencies.json, architecture.json,
diagnostics.json, acd/&lt;ClassName&gt;.puml, ccd/&lt;launch file stem&gt;.puml
Exit codes: 0 ok, 1 analysis finished with errors reported, 2 usage error.
</source>
        <translation>Aufruf:
  rosarch [workspace]                       die GUI öffnen (standardmäßig mit dem Beispiel-Workspace)
  rosarch recover &lt;workspace&gt; --out &lt;dir&gt; [--launch-arg name:=value]... [--launch-root &lt;file&gt;]
                                            die Stufen ohne GUI ausführen und die Artefakte schreiben
  rosarch eval --reference &lt;dir|file&gt; --recovered &lt;dir|file&gt; [--level acd|ccd] [--json]
                                            rekonstruierte PlantUML-Diagramme gegen eine Referenz bewerten
  rosarch suggest &lt;workspace&gt; --out &lt;dir&gt; [--llm-endpoint URL] [--llm-model NAME] [--llm-timeout S]
                                            geprüfte Vorschläge nach suggestions.json schreiben
                                            (ohne Endpunkt nur deterministische)
  rosarch --help | --version

Von recover geschriebene Artefakte: atomic_nodes.json, launch_dependencies.json, architecture.json,
diagnostics.json, acd/&lt;Klassenname&gt;.puml, ccd/&lt;Launch-File-Name ohne Endung&gt;.puml
Exit-Codes: 0 OK, 1 Analyse mit gemeldeten Fehlern beendet, 2 Aufruffehler.
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="57"/>
        <source>Recover the architecture of a ROS 2 workspace and write the artifacts.</source>
        <translation>Die Architektur eines ROS-2-Workspaces rekonstruieren und die Artefakte schreiben.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="62"/>
        <source>The workspace folder to analyse.</source>
        <translation>Der zu analysierende Workspace-Ordner.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="64"/>
        <source>Folder for the artifacts.</source>
        <translation>Ordner für die Artefakte.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="67"/>
        <source>Print only errors.</source>
        <translation>Nur Fehler ausgeben.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="69"/>
        <source>Set a launch argument (repeatable).</source>
        <translation>Ein Launch-Argument setzen (wiederholbar).</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="72"/>
        <source>Analyse only this launch file (relative to the workspace) as the root.</source>
        <translation>Nur dieses Launch-File (relativ zum Workspace) als Wurzel analysieren.</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="89"/>
        <source>recover needs a workspace folder and --out &lt;dir&gt;.

</source>
        <translation>recover benötigt einen Workspace-Ordner und --out &lt;dir&gt;.

</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="95"/>
        <source>Not a folder: %1
</source>
        <translation>Kein Ordner: %1
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="104"/>
        <source>--launch-arg expects name:=value, got &apos;%1&apos;.
</source>
        <translation>--launch-arg erwartet name:=value, erhalten: „%1“.
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="141"/>
        <source>Recovered %1 node classes with %2 ports in %3 packages; %4 launch files, %5 launch-file instances, %6 node instances, %7 unresolved items, %8 composites; in %9 ms; %10 diagnostics (%11 errors).
Wrote %12 files to %13
</source>
        <translation>%1 Knotenklassen mit %2 Ports in %3 Paketen rekonstruiert; %4 Launch-Files, %5 Launch-File-Instanzen, %6 Knoteninstanzen, %7 unaufgelöste Elemente, %8 Komposite; in %9 ms; %10 Diagnosen (%11 Fehler).
%12 Dateien nach %13 geschrieben
</translation>
    </message>
    <message>
        <location filename="../app/commandline.cpp" line="191"/>
        <source>Unknown command: %1

</source>
        <translation>Unbekannter Befehl: %1

</translation>
    </message>
</context>
<context>
    <name>rosarch::DiagnosticModel</name>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="50"/>
        <source>Info</source>
        <translation>Info</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="52"/>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="54"/>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="86"/>
        <source>At %1</source>
        <translation>In %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="100"/>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="102"/>
        <source>Location</source>
        <translation>Ort</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="104"/>
        <source>Code</source>
        <translation>Code</translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramController</name>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="96"/>
        <source>Export Diagram as &amp;SVG…</source>
        <translation>Diagramm als &amp;SVG exportieren…</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="97"/>
        <source>Write the composed diagram shown as an SVG drawing</source>
        <translation>Das angezeigte Kompositionsdiagramm als SVG-Zeichnung speichern</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="99"/>
        <source>Export Diagram as &amp;PNG…</source>
        <translation>Diagramm als &amp;PNG exportieren…</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="100"/>
        <source>Write the composed diagram shown as a PNG image</source>
        <translation>Das angezeigte Kompositionsdiagramm als PNG-Bild speichern</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="102"/>
        <source>&amp;Compare with Reference Model…</source>
        <translation>Mit &amp;Referenzmodell vergleichen…</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="103"/>
        <source>Score the recovered model against hand-written PlantUML diagrams and mark the differences in the composed diagram</source>
        <translation>Das rekonstruierte Modell gegen handgeschriebene PlantUML-Diagramme bewerten und die Unterschiede im Kompositionsdiagramm markieren</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="106"/>
        <source>C&amp;lear Comparison</source>
        <translation>&amp;Vergleich aufheben</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="132"/>
        <source>Composed diagram: %1</source>
        <translation>Kompositionsdiagramm: %1</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="230"/>
        <source>the reference has no diagram for %1</source>
        <translation>die Referenz enthält kein Diagramm für %1</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="258"/>
        <source>No ACD or CCD diagram could be read in %1.</source>
        <translation>In %1 konnte kein ACD- oder CCD-Diagramm gelesen werden.</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="270"/>
        <source>Compared with %1 (%2): micro F1 %3, macro F1 %4</source>
        <translation>Verglichen mit %1 (%2): Mikro-F1 %3, Makro-F1 %4</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="288"/>
        <source>Reference Model (folder of PlantUML diagrams)</source>
        <translation>Referenzmodell (Ordner mit PlantUML-Diagrammen)</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="294"/>
        <source>Comparison failed: %1</source>
        <translation>Vergleich fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="300"/>
        <source>Comparison with %1</source>
        <translation>Vergleich mit %1</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="319"/>
        <source>Exported the composed diagram to %1</source>
        <translation>Kompositionsdiagramm nach %1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="320"/>
        <source>Could not write the composed diagram to %1</source>
        <translation>Das Kompositionsdiagramm konnte nicht nach %1 geschrieben werden</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="321"/>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="321"/>
        <source>Export failed: %1</source>
        <translation>Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="333"/>
        <source>SVG drawing (*.svg)</source>
        <translation>SVG-Zeichnung (*.svg)</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="333"/>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="334"/>
        <source>Export Composed Diagram</source>
        <translation>Kompositionsdiagramm exportieren</translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramPanel</name>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="37"/>
        <source>Find in diagram</source>
        <translation>Im Diagramm suchen</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="38"/>
        <source>Highlights the parts, topics, services and namespaces whose name contains this text. Enter goes to the next match.</source>
        <translation>Hebt die Teile, Topics, Services und Namespaces hervor, deren Name diesen Text enthält. Enter springt zum nächsten Treffer.</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="47"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="47"/>
        <source>Show ports whose name comes from a parameter</source>
        <translation>Ports anzeigen, deren Name aus einem Parameter stammt</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="48"/>
        <source>Inactive</source>
        <translation>Inaktiv</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="49"/>
        <source>Show parts and ports whose launch condition or guard is false</source>
        <translation>Teile und Ports anzeigen, deren Launch-Bedingung oder Bedingung im Code falsch ist</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="50"/>
        <source>External</source>
        <translation>Extern</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="51"/>
        <source>Show includes of launch files outside the workspace</source>
        <translation>Includes von Launch-Files außerhalb des Workspaces anzeigen</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="53"/>
        <source>−</source>
        <translation>−</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="54"/>
        <source>Zoom out (-, Ctrl+wheel)</source>
        <translation>Verkleinern (-, Ctrl+Mausrad)</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="55"/>
        <source>+</source>
        <translation>+</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="56"/>
        <source>Zoom in (+, Ctrl+wheel)</source>
        <translation>Vergrößern (+, Ctrl+Mausrad)</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="57"/>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="58"/>
        <source>Fit the whole diagram in the view (0)</source>
        <translation>Das ganze Diagramm in die Ansicht einpassen (0)</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="59"/>
        <source>Export…</source>
        <translation>Exportieren…</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="61"/>
        <source>Export Diagram</source>
        <translation>Diagramm exportieren</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="63"/>
        <source>SVG image (*.svg);;PNG image (*.png)</source>
        <translation>SVG-Bild (*.svg);;PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="68"/>
        <source>Save the whole diagram as SVG or PNG</source>
        <translation>Das ganze Diagramm als SVG oder PNG speichern</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="89"/>
        <location filename="../widgets/diagrampanel.cpp" line="245"/>
        <source>No composed diagram yet. Run stage 3 to compose the launch files.</source>
        <translation>Noch kein Kompositionsdiagramm. Führen Sie Stufe 3 aus, um die Launch-Files zusammenzusetzen.</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="246"/>
        <source>This launch file is not part of the architecture.</source>
        <translation>Dieses Launch-File ist nicht Teil der Architektur.</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="255"/>
        <source>%1 starts no nodes and includes no launch files.</source>
        <translation>%1 startet keine Knoten und bindet keine Launch-Files ein.</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="256"/>
        <source>Every element of %1 is hidden by the filters.</source>
        <translation>Alle Elemente von %1 sind durch die Filter ausgeblendet.</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="274"/>
        <source>Laying out…</source>
        <translation>Layout wird berechnet…</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="302"/>
        <source>%1

Collapse namespaces or hide elements to make the diagram smaller, then try again.</source>
        <translation>%1

Klappen Sie Namespaces ein oder blenden Sie Elemente aus, um das Diagramm zu verkleinern, und versuchen Sie es dann erneut.</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="437"/>
        <source>Expand Namespace %1</source>
        <translation>Namespace %1 ausklappen</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="438"/>
        <location filename="../widgets/diagrampanel.cpp" line="455"/>
        <source>Collapse Namespace %1</source>
        <translation>Namespace %1 einklappen</translation>
    </message>
    <message>
        <location filename="../widgets/diagrampanel.cpp" line="447"/>
        <source>Open %1</source>
        <translation>%1 öffnen</translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramScene</name>
    <message>
        <location filename="../widgets/diagramscene.cpp" line="207"/>
        <source>Composed diagram exported by rosarch</source>
        <translation>Von rosarch exportiertes Kompositionsdiagramm</translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramText</name>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="17"/>
        <source>Publisher</source>
        <translation>Publisher</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="19"/>
        <source>Subscriber</source>
        <translation>Subscriber</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="21"/>
        <source>Service server</source>
        <translation>Service-Server</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="23"/>
        <source>Service client</source>
        <translation>Service-Client</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="25"/>
        <source>Action server</source>
        <translation>Action-Server</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="27"/>
        <source>Action client</source>
        <translation>Action-Client</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="36"/>
        <source>publishes to</source>
        <translation>publiziert auf</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="38"/>
        <source>subscribes to</source>
        <translation>abonniert</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="40"/>
        <source>calls</source>
        <translation>ruft auf</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="42"/>
        <source>serves</source>
        <translation>bedient</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="45"/>
        <source>is delegated to the boundary port</source>
        <translation>wird an den Randport delegiert</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="60"/>
        <source>Included launch file %1 (outside the workspace)</source>
        <translation>Eingebundenes Launch-File %1 (außerhalb des Workspaces)</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="61"/>
        <source>Included launch file %1 — double-click to open</source>
        <translation>Eingebundenes Launch-File %1 – Doppelklick zum Öffnen</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="64"/>
        <source>Node %1 : %2</source>
        <translation>Knoten %1 : %2</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="66"/>
        <source>The class was not found; its ports are unknown.</source>
        <translation>Die Klasse wurde nicht gefunden; ihre Ports sind unbekannt.</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="68"/>
        <source>Namespace: %1</source>
        <translation>Namespace: %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="71"/>
        <source>Inactive: its launch condition is false.</source>
        <translation>Inaktiv: Die Launch-Bedingung ist falsch.</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="72"/>
        <source>Started at %1</source>
        <translation>Gestartet in %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="82"/>
        <source>Written as: %1</source>
        <translation>Geschrieben als: %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="84"/>
        <source>The name could not be resolved statically; this is a guess.</source>
        <translation>Der Name konnte nicht statisch aufgelöst werden; dies ist eine Annahme.</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="86"/>
        <source>The name comes from a parameter.</source>
        <translation>Der Name stammt aus einem Parameter.</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="88"/>
        <source>Remapped by the launch file.</source>
        <translation>Vom Launch-File per Remap umbenannt.</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="90"/>
        <source>Guard: %1</source>
        <translation>Bedingung: %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="91"/>
        <source>Guard (false here): %1</source>
        <translation>Bedingung (hier falsch): %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="93"/>
        <source>Created at %1</source>
        <translation>Erzeugt in %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="108"/>
        <source>Namespace %1 — right-click to collapse or expand</source>
        <translation>Namespace %1 – Rechtsklick zum Ein- oder Ausklappen</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="111"/>
        <source>Topic %1</source>
        <translation>Topic %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="112"/>
        <source>Service %1</source>
        <translation>Service %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="113"/>
        <source>Action %1</source>
        <translation>Action %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="119"/>
        <source>Boundary port %1: %2 %3</source>
        <translation>Randport %1: %2 %3</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="120"/>
        <source>Promoted: nothing inside this launch file is on the other side.</source>
        <translation>Nach außen geführt: Innerhalb dieses Launch-Files gibt es keine Gegenseite.</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="129"/>
        <source>%1 (%2) %3 %4 — click to see the code</source>
        <translation>%1 (%2) %3 %4 – Klicken, um den Code zu sehen</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="144"/>
        <source>1 element of the reference is missing: %1</source>
        <translation>1 Element der Referenz fehlt: %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="145"/>
        <source>%1 elements of the reference are missing: %2</source>
        <translation>%1 Elemente der Referenz fehlen: %2</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="150"/>
        <source>launch file (outside the workspace)</source>
        <translation>Launch-File (außerhalb des Workspaces)</translation>
    </message>
    <message>
        <location filename="../widgets/diagramtext.cpp" line="151"/>
        <source>launch file %1</source>
        <translation>Launch-File %1</translation>
    </message>
</context>
<context>
    <name>rosarch::Document</name>
    <message>
        <location filename="../document/setnodedescriptioncommand.cpp" line="13"/>
        <source>Edit description</source>
        <translation>Beschreibung bearbeiten</translation>
    </message>
    <message>
        <location filename="../document/decidesuggestioncommand.cpp" line="13"/>
        <source>Accept suggestion</source>
        <translation>Vorschlag annehmen</translation>
    </message>
    <message>
        <location filename="../document/decidesuggestioncommand.cpp" line="14"/>
        <source>Reject suggestion</source>
        <translation>Vorschlag ablehnen</translation>
    </message>
    <message>
        <location filename="../document/document.cpp" line="149"/>
        <source>Accept %1 suggestions</source>
        <translation>%1 Vorschläge annehmen</translation>
    </message>
</context>
<context>
    <name>rosarch::EvalCommand</name>
    <message>
        <location filename="../app/evalcommand.cpp" line="30"/>
        <source>error: %1
</source>
        <translation>Fehler: %1
</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="33"/>
        <source>note: </source>
        <translation>Hinweis: </translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="35"/>
        <source>warning: </source>
        <translation>Warnung: </translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="47"/>
        <source>Score a recovered PlantUML model against a reference model.</source>
        <translation>Ein rekonstruiertes PlantUML-Modell gegen ein Referenzmodell bewerten.</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="52"/>
        <source>The reference model: a .puml file or a folder of them (searched recursively).</source>
        <translation>Das Referenzmodell: eine .puml-Datei oder ein Ordner mit solchen Dateien (rekursiv durchsucht).</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="57"/>
        <source>The recovered model: a .puml file or a folder of them.</source>
        <translation>Das rekonstruierte Modell: eine .puml-Datei oder ein Ordner mit solchen Dateien.</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="61"/>
        <source>Evaluate only ACDs or only CCDs (default: every level present).</source>
        <translation>Nur ACDs oder nur CCDs bewerten (Standard: jede vorhandene Ebene).</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="64"/>
        <source>Print the result as JSON.</source>
        <translation>Das Ergebnis als JSON ausgeben.</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="70"/>
        <source>Usage: rosarch eval --reference &lt;dir|file&gt; --recovered &lt;dir|file&gt; [--level acd|ccd] [--json]
</source>
        <translation>Aufruf: rosarch eval --reference &lt;dir|file&gt; --recovered &lt;dir|file&gt; [--level acd|ccd] [--json]
</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="82"/>
        <source>eval needs --reference and --recovered, and no other arguments.

</source>
        <translation>eval benötigt --reference und --recovered und keine weiteren Argumente.

</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="90"/>
        <source>--level expects acd or ccd, got &apos;%1&apos;.
</source>
        <translation>--level erwartet acd oder ccd, erhalten: „%1“.
</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="100"/>
        <source>eval: %1
</source>
        <translation>eval: %1
</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="116"/>
        <source>Nothing to evaluate: no ACD or CCD found in either input.
</source>
        <translation>Nichts zu bewerten: In keiner der Eingaben wurde ein ACD oder CCD gefunden.
</translation>
    </message>
    <message>
        <location filename="../app/evalcommand.cpp" line="123"/>
        <source>eval: %1 is neither an ACD nor a CCD
</source>
        <translation>eval: %1 ist weder ein ACD noch ein CCD
</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="35"/>
        <source>ACD (AtomicClassifierDiagrams)</source>
        <translation>ACD (AtomicClassifierDiagrams)</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="36"/>
        <source>CCD (ComposedClassifierDiagrams)</source>
        <translation>CCD (ComposedClassifierDiagrams)</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="49"/>
        <source>%1 reference diagrams, %2 recovered: %3 matched, %4 missing, %5 extra
</source>
        <translation>%1 Referenzdiagramme, %2 rekonstruiert: %3 zugeordnet, %4 fehlend, %5 zusätzlich
</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="56"/>
        <source>kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="57"/>
        <source>TP</source>
        <translation>TP</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="58"/>
        <source>FP</source>
        <translation>FP</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="59"/>
        <source>FN</source>
        <translation>FN</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="60"/>
        <source>micro P/R/F1</source>
        <translation>Mikro-P/R/F1</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="61"/>
        <source>macro P/R/F1</source>
        <translation>Makro-P/R/F1</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="67"/>
        <source>all kinds</source>
        <translation>alle Arten</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="69"/>
        <source>Per diagram (P R F1 over all kinds):
</source>
        <translation>Je Diagramm (P R F1 über alle Arten):
</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="74"/>
        <source>   missing: no recovered diagram</source>
        <translation>   fehlt: kein rekonstruiertes Diagramm</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="76"/>
        <source>  extra recovered diagram, not scored: %1 (%2)
</source>
        <translation>  zusätzliches rekonstruiertes Diagramm, nicht bewertet: %1 (%2)
</translation>
    </message>
    <message>
        <location filename="../app/evaluationreport.cpp" line="86"/>
        <source>Differences (FP: recovered but not in the reference; FN: in the reference but not recovered):
</source>
        <translation>Unterschiede (FP: rekonstruiert, aber nicht in der Referenz; FN: in der Referenz, aber nicht rekonstruiert):
</translation>
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
        <location filename="../widgets/launchtreepanel.cpp" line="16"/>
        <source>&amp;Go to Class</source>
        <translation>Zur &amp;Klasse wechseln</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="20"/>
        <source>Filter by name, namespace, class or executable</source>
        <translation>Nach Name, Namespace, Klasse oder Executable filtern</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="21"/>
        <source>Shows the launch files, namespaces and node instances whose name, namespace, class or executable contains this text. Esc clears the filter.</source>
        <translation>Zeigt die Launch-Files, Namespaces und Knoteninstanzen, deren Name, Namespace, Klasse oder Executable diesen Text enthält. Esc setzt den Filter zurück.</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="29"/>
        <source>Select the atomic node class this node instance runs</source>
        <translation>Die atomare Knotenklasse auswählen, die diese Knoteninstanz ausführt</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="37"/>
        <source>&amp;Expand All</source>
        <translation>Alle &amp;ausklappen</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="39"/>
        <source>&amp;Collapse All</source>
        <translation>Alle &amp;einklappen</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="58"/>
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
    <name>rosarch::LlmSettingsDialog</name>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="17"/>
        <source>Ask a language model for suggestions</source>
        <translation>Ein Sprachmodell nach Vorschlägen fragen</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="23"/>
        <source>LLM Settings</source>
        <translation>LLM-Einstellungen</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="26"/>
        <source>Without a model, rosarch still proposes descriptions and groupings from the code. Any OpenAI-compatible server works: OpenAI, Ollama, llama.cpp server, vLLM.</source>
        <translation>Auch ohne Modell schlägt rosarch Beschreibungen und Gruppierungen aus dem Code vor. Jeder OpenAI-kompatible Server funktioniert: OpenAI, Ollama, llama.cpp-Server, vLLM.</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="32"/>
        <source>The server&apos;s base URL; /v1/chat/completions is added</source>
        <translation>Die Basis-URL des Servers; /v1/chat/completions wird angehängt</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="37"/>
        <source>0 keeps replies as repeatable as the server allows</source>
        <translation>Mit 0 sind die Antworten so reproduzierbar, wie der Server es zulässt</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="39"/>
        <location filename="../widgets/llmsettingsdialog.cpp" line="41"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="42"/>
        <source>How long one prompt may take, streaming included</source>
        <translation>Wie lange ein Prompt dauern darf, einschließlich Streaming</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="52"/>
        <source>&amp;Endpoint:</source>
        <translation>&amp;Endpunkt:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="53"/>
        <source>&amp;Model:</source>
        <translation>&amp;Modell:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="54"/>
        <source>&amp;Temperature:</source>
        <translation>&amp;Temperatur:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="55"/>
        <source>&amp;Connect timeout:</source>
        <translation>&amp;Verbindungs-Timeout:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="56"/>
        <source>&amp;Request timeout:</source>
        <translation>&amp;Anfrage-Timeout:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="57"/>
        <source>API key:</source>
        <translation>API-Schlüssel:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="87"/>
        <source>Set in ROSARCH_LLM_API_KEY (not shown, never stored).</source>
        <translation>In ROSARCH_LLM_API_KEY gesetzt (nicht angezeigt, nie gespeichert).</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="89"/>
        <source>Set in OPENAI_API_KEY (not shown, never stored).</source>
        <translation>In OPENAI_API_KEY gesetzt (nicht angezeigt, nie gespeichert).</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="90"/>
        <source>Not set. Local servers need none; for a hosted API set ROSARCH_LLM_API_KEY or OPENAI_API_KEY in the environment before starting rosarch.</source>
        <translation>Nicht gesetzt. Lokale Server benötigen keinen; setzen Sie für eine gehostete API vor dem Start von rosarch ROSARCH_LLM_API_KEY oder OPENAI_API_KEY in der Umgebung.</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="132"/>
        <source>Enter the server&apos;s URL, e.g. http://localhost:11434/v1 for Ollama.</source>
        <translation>Geben Sie die URL des Servers ein, z. B. http://localhost:11434/v1 für Ollama.</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="137"/>
        <source>The endpoint must be an http:// or https:// URL.</source>
        <translation>Der Endpunkt muss eine http://- oder https://-URL sein.</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="139"/>
        <source>Enter the model name the server knows, e.g. llama3.1 or gpt-4o-mini.</source>
        <translation>Geben Sie den Modellnamen ein, den der Server kennt, z. B. llama3.1 oder gpt-4o-mini.</translation>
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
        <location filename="../app/mainwindow.cpp" line="61"/>
        <source>rosarch</source>
        <translation>rosarch</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="123"/>
        <source>Atomic nodes</source>
        <translation>Atomare Knoten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="124"/>
        <source>Launch tree</source>
        <translation>Launch-Baum</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="125"/>
        <source>Composed diagram</source>
        <translation>Kompositionsdiagramm</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="126"/>
        <source>Source</source>
        <translation>Quelltext</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="127"/>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="25"/>
        <source>&amp;Open Workspace…</source>
        <translation>Workspace ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="27"/>
        <source>Open a ROS 2 workspace folder and recover its architecture</source>
        <translation>Einen ROS-2-Workspace-Ordner öffnen und seine Architektur rekonstruieren</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="30"/>
        <source>&amp;Export Artifacts…</source>
        <translation>Artefakte &amp;exportieren…</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="31"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="33"/>
        <source>Write the JSON artifacts and the PlantUML diagrams: one per node class (ACD) and one per launch file (CCD)</source>
        <translation>Die JSON-Artefakte und die PlantUML-Diagramme schreiben: eines pro Knotenklasse (ACD) und eines pro Launch-File (CCD)</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="37"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="42"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="44"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="47"/>
        <source>&amp;Find…</source>
        <translation>&amp;Suchen…</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="63"/>
        <source>&amp;Next Diagnostic</source>
        <translation>&amp;Nächste Diagnose</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="69"/>
        <source>&amp;Previous Diagnostic</source>
        <translation>&amp;Vorherige Diagnose</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="49"/>
        <source>Filter the node tree, or the launch tree when it has the focus, by name</source>
        <translation>Den Knotenbaum – oder den Launch-Baum, wenn er den Fokus hat – nach Name filtern</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="76"/>
        <source>&amp;Run All Stages</source>
        <translation>Alle Stufen aus&amp;führen</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="77"/>
        <source>Run all</source>
        <translation>Alle ausführen</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="79"/>
        <source>Recover the atomic nodes, the launch tree and the composed architecture of the workspace (F5)</source>
        <translation>Die atomaren Knoten, den Launch-Baum und die zusammengesetzte Architektur des Workspaces rekonstruieren (F5)</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="81"/>
        <source>Stage 1 finds node classes, their ports and executables; stage 2 reads the launch files; stage 3 composes them</source>
        <translation>Stufe 1 findet Knotenklassen, ihre Ports und Executables; Stufe 2 liest die Launch-Files; Stufe 3 setzt sie zusammen</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="85"/>
        <source>Run Stage &amp;2: Launch Files</source>
        <translation>Stufe &amp;2 ausführen: Launch-Files</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="86"/>
        <source>Stage 2</source>
        <translation>Stufe 2</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="88"/>
        <source>Read the launch files again against the current atomic nodes, with the chosen launch arguments (F6)</source>
        <translation>Die Launch-Files mit den gewählten Launch-Argumenten erneut lesen und mit den aktuellen atomaren Knoten abgleichen (F6)</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="90"/>
        <source>Re-run stage 2 only: launch files, includes, namespaces and node instances</source>
        <translation>Nur Stufe 2 erneut ausführen: Launch-Files, Includes, Namespaces und Knoteninstanzen</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="94"/>
        <source>Launch &amp;Arguments…</source>
        <translation>&amp;Launch-Argumente…</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="95"/>
        <source>Arguments</source>
        <translation>Argumente</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="96"/>
        <source>Ctrl+Shift+A</source>
        <translation>Ctrl+Shift+A</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="98"/>
        <source>Choose the root launch file and the launch argument values for stage 2</source>
        <translation>Das Wurzel-Launch-File und die Werte der Launch-Argumente für Stufe 2 wählen</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="102"/>
        <source>&amp;Cancel Stage</source>
        <translation>Stufe &amp;abbrechen</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="103"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="105"/>
        <source>Stop the running stage and keep the previous result (Esc)</source>
        <translation>Die laufende Stufe anhalten und das vorherige Ergebnis behalten (Esc)</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="108"/>
        <source>&amp;Suggest (Stage 4)</source>
        <translation>&amp;Vorschläge (Stufe 4)</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="109"/>
        <source>LLM</source>
        <translation>LLM</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="111"/>
        <source>Propose node descriptions and subsystem groupings for review (F7); asks the LLM when one is configured</source>
        <translation>Knotenbeschreibungen und Subsystem-Gruppierungen zur Prüfung vorschlagen (F7); fragt das LLM, wenn eines konfiguriert ist</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="121"/>
        <source>&amp;Reset Layout</source>
        <translation>Layout &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="124"/>
        <source>&amp;About rosarch</source>
        <translation>&amp;Über rosarch</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="130"/>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="137"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="139"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="151"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="160"/>
        <source>Main</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="172"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="176"/>
        <source>&amp;Toolbar</source>
        <translation>&amp;Werkzeugleiste</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="181"/>
        <source>&amp;Stages</source>
        <translation>&amp;Stufen</translation>
    </message>
    <message>
        <location filename="../app/mainwindowactions.cpp" line="190"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="132"/>
        <source>Suggestions</source>
        <translation>Vorschläge</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="273"/>
        <source>Open ROS 2 Workspace</source>
        <translation>ROS-2-Workspace öffnen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="284"/>
        <source>Cannot open workspace</source>
        <translation>Workspace kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="285"/>
        <source>The folder “%1” does not exist or is not a folder.

Choose a ROS 2 workspace (a folder containing packages with a package.xml) with File → Open Workspace, or drop one onto the window.</source>
        <translation>Der Ordner „%1“ existiert nicht oder ist kein Ordner.

Wählen Sie über Datei → Workspace öffnen einen ROS-2-Workspace (einen Ordner mit Paketen, die eine package.xml enthalten) aus, oder ziehen Sie einen Workspace auf das Fenster.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="299"/>
        <source>%1 — rosarch</source>
        <translation>%1 — rosarch</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="342"/>
        <source>No recent workspaces</source>
        <translation>Keine zuletzt geöffneten Workspaces</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="347"/>
        <source>&amp;%1 %2 — %3</source>
        <translation>&amp;%1 %2 — %3</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="355"/>
        <source>&amp;Clear Menu</source>
        <translation>Menü &amp;leeren</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="366"/>
        <source>Export Artifacts To</source>
        <translation>Artefakte exportieren nach</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="381"/>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="382"/>
        <source>The artifacts could not be written to “%1”:
%2

Choose a folder you can write to, or free some space, and export again.</source>
        <translation>Die Artefakte konnten nicht nach „%1“ geschrieben werden:
%2

Wählen Sie einen Ordner, in den Sie schreiben dürfen, oder geben Sie Speicherplatz frei, und exportieren Sie erneut.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="385"/>
        <source>Export to %1 failed: %2</source>
        <translation>Export nach %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="388"/>
        <source>Exported 1 file to %1</source>
        <translation>1 Datei nach %1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="389"/>
        <source>Exported %1 files to %2</source>
        <translation>%1 Dateien nach %2 exportiert</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="423"/>
        <source>1 package</source>
        <translation>1 Paket</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="423"/>
        <source>%1 packages</source>
        <translation>%1 Pakete</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="424"/>
        <source>1 node</source>
        <translation>1 Knoten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="424"/>
        <source>%1 nodes</source>
        <translation>%1 Knoten</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="425"/>
        <source>1 port</source>
        <translation>1 Port</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="425"/>
        <source>%1 ports</source>
        <translation>%1 Ports</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="426"/>
        <source>1 launch file</source>
        <translation>1 Launch-File</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="426"/>
        <source>%1 launch files</source>
        <translation>%1 Launch-Files</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="427"/>
        <source>1 instance</source>
        <translation>1 Instanz</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="427"/>
        <source>%1 instances</source>
        <translation>%1 Instanzen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="428"/>
        <source>1 unresolved</source>
        <translation>1 unaufgelöst</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="428"/>
        <source>%1 unresolved</source>
        <translation>%1 unaufgelöst</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="429"/>
        <source>1 composite</source>
        <translation>1 Komposit</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="429"/>
        <source>%1 composites</source>
        <translation>%1 Komposite</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="430"/>
        <source>1 diagnostic</source>
        <translation>1 Diagnose</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="430"/>
        <source>%1 diagnostics</source>
        <translation>%1 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="432"/>
        <source>Stage 1: packages, atomic node classes and their ports.
Stage 2: launch files found, node instances they start and expressions that could not be resolved statically.
Stage 3: composites, one per launch-file instance.</source>
        <translation>Stufe 1: Pakete, atomare Knotenklassen und ihre Ports.
Stufe 2: gefundene Launch-Files, die von ihnen gestarteten Knoteninstanzen und Ausdrücke, die nicht statisch aufgelöst werden konnten.
Stufe 3: Komposite, eines pro Launch-File-Instanz.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="447"/>
        <source>Open a ROS 2 workspace (File → Open Workspace) to see its launch tree.</source>
        <translation>Öffnen Sie einen ROS-2-Workspace (Datei → Workspace öffnen), um seinen Launch-Baum zu sehen.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="449"/>
        <source>Reading the launch files…</source>
        <translation>Die Launch-Files werden gelesen…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="452"/>
        <source>No launch files found in this workspace.

Stage 2 reads *.launch.py, *.launch.xml and *.launch.yaml files and any file holding a launch description.</source>
        <translation>In diesem Workspace wurden keine Launch-Files gefunden.

Stufe 2 liest *.launch.py-, *.launch.xml- und *.launch.yaml-Dateien sowie jede Datei, die eine Launch-Beschreibung enthält.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="457"/>
        <source>No launch file was analysed as a root.

Choose one in Stages → Launch Arguments…</source>
        <translation>Es wurde kein Launch-File als Wurzel analysiert.

Wählen Sie eines unter Stufen → Launch-Argumente…</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="487"/>
        <source>[%1/%2] %3</source>
        <translation>[%1/%2] %3</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="139"/>
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
        <location filename="../app/stagecontroller.cpp" line="103"/>
        <source>Reading launch files…</source>
        <translation>Launch-Files werden gelesen…</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="99"/>
        <source>Stages 1–3 (atomic nodes, launch files, composition) started on %1</source>
        <translation>Stufen 1–3 (atomare Knoten, Launch-Files, Komposition) für %1 gestartet</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="100"/>
        <source>Recovering atomic nodes, launch files and their composition…</source>
        <translation>Atomare Knoten, Launch-Files und ihre Komposition werden rekonstruiert…</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="102"/>
        <source>Stages 2–3 (launch files, composition) started on %1</source>
        <translation>Stufen 2–3 (Launch-Files, Komposition) für %1 gestartet</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="119"/>
        <source>Stages 1–3 finished in %1 s: %2 nodes, %3 ports, %4 launch files, %5 node instances, %6 composites, %7 diagnostics</source>
        <translation>Stufen 1–3 in %1 s abgeschlossen: %2 Knoten, %3 Ports, %4 Launch-Files, %5 Knoteninstanzen, %6 Komposite, %7 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="135"/>
        <source>Stages 2–3 finished in %1 s: %2 launch files, %3 launch-file instances, %4 node instances, %5 composites, %6 diagnostics</source>
        <translation>Stufen 2–3 in %1 s abgeschlossen: %2 Launch-Files, %3 Launch-File-Instanzen, %4 Knoteninstanzen, %5 Komposite, %6 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="153"/>
        <source>Stages 1–3</source>
        <translation>Stufen 1–3</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="153"/>
        <source>Stages 2–3</source>
        <translation>Stufen 2–3</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="154"/>
        <source>%1 canceled; the previous result is kept.</source>
        <translation>%1 abgebrochen; das vorherige Ergebnis bleibt erhalten.</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="155"/>
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
<context>
    <name>rosarch::SuggestCommand</name>
    <message>
        <location filename="../app/suggestcommand.cpp" line="21"/>
        <source>Recover a ROS 2 workspace and propose checked suggestions (node descriptions, subsystem groupings, unresolved names).</source>
        <translation>Einen ROS-2-Workspace rekonstruieren und geprüfte Vorschläge machen (Knotenbeschreibungen, Subsystem-Gruppierungen, unaufgelöste Namen).</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="25"/>
        <source>The workspace folder to analyse.</source>
        <translation>Der zu analysierende Workspace-Ordner.</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="27"/>
        <source>Folder for suggestions.json.</source>
        <translation>Ordner für suggestions.json.</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="29"/>
        <source>OpenAI-compatible endpoint (with or without /v1); default $ROSARCH_LLM_ENDPOINT. The API key is read from $ROSARCH_LLM_API_KEY or $OPENAI_API_KEY.</source>
        <translation>OpenAI-kompatibler Endpunkt (mit oder ohne /v1); Standard: $ROSARCH_LLM_ENDPOINT. Der API-Schlüssel wird aus $ROSARCH_LLM_API_KEY oder $OPENAI_API_KEY gelesen.</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="33"/>
        <source>Model name; default $ROSARCH_LLM_MODEL.</source>
        <translation>Modellname; Standard: $ROSARCH_LLM_MODEL.</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="35"/>
        <source>Request timeout in seconds (default 120).</source>
        <translation>Timeout einer Anfrage in Sekunden (Standard: 120).</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="37"/>
        <source>Folder whose prompt files override the built-in ones; default $ROSARCH_PROMPT_DIR.</source>
        <translation>Ordner, dessen Prompt-Dateien die eingebauten ersetzen; Standard: $ROSARCH_PROMPT_DIR.</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="40"/>
        <source>Print only errors.</source>
        <translation>Nur Fehler ausgeben.</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="53"/>
        <source>suggest needs a workspace folder and --out &lt;dir&gt;.
</source>
        <translation>suggest benötigt einen Workspace-Ordner und --out &lt;dir&gt;.
</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="58"/>
        <source>Not a folder: %1
</source>
        <translation>Kein Ordner: %1
</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="72"/>
        <source>--llm-timeout expects a positive number of seconds, got &apos;%1&apos;.
</source>
        <translation>--llm-timeout erwartet eine positive Anzahl Sekunden, erhalten: „%1“.
</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="85"/>
        <source>LLM: %1
</source>
        <translation>LLM: %1
</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="90"/>
        <source>LLM error: %1
</source>
        <translation>LLM-Fehler: %1
</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="98"/>
        <source>Cannot create %1
</source>
        <translation>%1 kann nicht erstellt werden
</translation>
    </message>
    <message>
        <location filename="../app/suggestcommand.cpp" line="115"/>
        <source>%1 suggestions (%2); %3 discarded (%4); %5 prompts, ~%6 tokens (characters / 4).
Wrote %7
</source>
        <translation>%1 Vorschläge (%2); %3 verworfen (%4); %5 Prompts, ~%6 Tokens (Zeichen / 4).
%7 geschrieben
</translation>
    </message>
</context>
<context>
    <name>rosarch::SuggestionController</name>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="35"/>
        <source>Suggestions: accepted %1 (%2) as one step (Undo takes it back)</source>
        <translation>Vorschläge: %1 (%2) in einem Schritt angenommen (Rückgängig nimmt sie zurück)</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="58"/>
        <source>Suggestions: %1</source>
        <translation>Vorschläge: %1</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="64"/>
        <source>Suggestions: the decisions could not be saved: %1</source>
        <translation>Vorschläge: Die Entscheidungen konnten nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="91"/>
        <source>Suggestions need a recovered model: open a workspace and run the stages first.</source>
        <translation>Vorschläge benötigen ein rekonstruiertes Modell: Öffnen Sie einen Workspace und führen Sie zuerst die Stufen aus.</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="93"/>
        <source>Nothing to suggest on yet</source>
        <translation>Noch keine Grundlage für Vorschläge</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="100"/>
        <source>Suggestions: the LLM is turned on but has no endpoint; only the deterministic suggestions are made (LLM Settings…).</source>
        <translation>Vorschläge: Das LLM ist eingeschaltet, hat aber keinen Endpunkt; es werden nur die deterministischen Vorschläge gemacht (LLM-Einstellungen…).</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="121"/>
        <source>LLM settings: %1</source>
        <translation>LLM-Einstellungen: %1</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="122"/>
        <source>LLM settings: the LLM is off; suggestions come from the code only</source>
        <translation>LLM-Einstellungen: Das LLM ist aus; Vorschläge stammen nur aus dem Code</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="129"/>
        <source>LLM off</source>
        <translation>LLM aus</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="133"/>
        <source>LLM: %1 at %2</source>
        <translation>LLM: %1 auf %2</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="139"/>
        <source>Asking the LLM…</source>
        <translation>Das LLM wird gefragt…</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="139"/>
        <source>Reading the code…</source>
        <translation>Der Code wird gelesen…</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="140"/>
        <source>Suggestions started (deterministic, then the LLM)</source>
        <translation>Vorschläge gestartet (deterministisch, danach das LLM)</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="141"/>
        <source>Suggestions started (deterministic; the LLM is off)</source>
        <translation>Vorschläge gestartet (deterministisch; das LLM ist aus)</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="142"/>
        <source>Looking for suggestions…</source>
        <translation>Vorschläge werden gesucht…</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="148"/>
        <source>%1: %L2 characters received</source>
        <translation>%1: %L2 Zeichen empfangen</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="163"/>
        <source>1 description</source>
        <translation>1 Beschreibung</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="163"/>
        <source>%1 descriptions</source>
        <translation>%1 Beschreibungen</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="165"/>
        <source>1 grouping</source>
        <translation>1 Gruppierung</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="165"/>
        <source>%1 groupings</source>
        <translation>%1 Gruppierungen</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="167"/>
        <source>1 name</source>
        <translation>1 Name</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="167"/>
        <source>%1 names</source>
        <translation>%1 Namen</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="168"/>
        <source>Suggestions: %1 new</source>
        <translation>Vorschläge: %1 neu</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="172"/>
        <source>, %1 already decided</source>
        <translation>, %1 bereits entschieden</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="177"/>
        <source>, %1 discarded: %2</source>
        <translation>, %1 verworfen: %2</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="191"/>
        <source>Suggestions: the LLM failed: %1 The suggestions from the code are shown; check LLM Settings… and run again.</source>
        <translation>Vorschläge: Das LLM ist fehlgeschlagen: %1 Die Vorschläge aus dem Code werden angezeigt; prüfen Sie die LLM-Einstellungen… und führen Sie den Lauf erneut aus.</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="195"/>
        <source>Done: code and %1</source>
        <translation>Fertig: Code und %1</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="196"/>
        <source>Done: from the code</source>
        <translation>Fertig: aus dem Code</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="199"/>
        <source>The LLM failed; see the log</source>
        <translation>Das LLM ist fehlgeschlagen; siehe Protokoll</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="200"/>
        <source>Suggestions: the LLM failed (see the log); the suggestions from the code are shown</source>
        <translation>Vorschläge: Das LLM ist fehlgeschlagen (siehe Protokoll); die Vorschläge aus dem Code werden angezeigt</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="211"/>
        <source>Canceled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="213"/>
        <source>Suggestions canceled; %1</source>
        <translation>Vorschläge abgebrochen; %1</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="214"/>
        <source>Suggestions canceled</source>
        <translation>Vorschläge abgebrochen</translation>
    </message>
</context>
<context>
    <name>rosarch::SuggestionModel</name>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="103"/>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="105"/>
        <source>Grouping</source>
        <translation>Gruppierung</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="107"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="116"/>
        <source>Descriptions</source>
        <translation>Beschreibungen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="118"/>
        <source>Groupings</source>
        <translation>Gruppierungen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="120"/>
        <source>Names</source>
        <translation>Namen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="129"/>
        <source>Pending</source>
        <translation>Offen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="131"/>
        <source>Accepted</source>
        <translation>Angenommen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="133"/>
        <source>Rejected</source>
        <translation>Abgelehnt</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="227"/>
        <source>deterministic</source>
        <translation>deterministisch</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="268"/>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="297"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="299"/>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="301"/>
        <source>Proposal</source>
        <translation>Vorschlag</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="303"/>
        <source>Origin</source>
        <translation>Herkunft</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="305"/>
        <source>Evidence</source>
        <translation>Belege</translation>
    </message>
</context>
<context>
    <name>rosarch::SuggestionPanel</name>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="63"/>
        <source>All statuses</source>
        <translation>Alle Status</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="68"/>
        <source>Show the suggestions of one status</source>
        <translation>Die Vorschläge mit einem bestimmten Status anzeigen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="69"/>
        <source>All kinds</source>
        <translation>Alle Arten</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="74"/>
        <source>Show the suggestions of one kind</source>
        <translation>Die Vorschläge einer bestimmten Art anzeigen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="162"/>
        <source>Select a suggestion to see its rationale and evidence.</source>
        <translation>Wählen Sie einen Vorschlag aus, um Begründung und Belege zu sehen.</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="185"/>
        <source>Run Suggestions</source>
        <translation>Vorschläge ermitteln</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="186"/>
        <source>Propose node descriptions and subsystem groupings from the code (and ask the LLM when one is configured)</source>
        <translation>Knotenbeschreibungen und Subsystem-Gruppierungen aus dem Code vorschlagen (und das LLM fragen, wenn eines konfiguriert ist)</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="189"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="190"/>
        <source>Stop asking the LLM; what arrived so far is kept</source>
        <translation>Das LLM nicht weiter fragen; bereits Empfangenes bleibt erhalten</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="192"/>
        <source>LLM Settings…</source>
        <translation>LLM-Einstellungen…</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="193"/>
        <source>Endpoint, model and timeouts of the language model</source>
        <translation>Endpunkt, Modell und Timeouts des Sprachmodells</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="196"/>
        <source>Accept</source>
        <translation>Annehmen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="197"/>
        <source>Apply the proposed change (Enter); undo with Ctrl+Z</source>
        <translation>Die vorgeschlagene Änderung übernehmen (Enter); rückgängig mit Ctrl+Z</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="199"/>
        <source>Reject</source>
        <translation>Ablehnen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="200"/>
        <source>Dismiss the proposal; it is not asked again (Delete)</source>
        <translation>Den Vorschlag verwerfen; er wird nicht erneut gestellt (Entf)</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="202"/>
        <location filename="../widgets/suggestionpanel.cpp" line="427"/>
        <source>Accept All</source>
        <translation>Alle annehmen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="203"/>
        <source>Accept every pending suggestion of this kind, as one step on the undo stack</source>
        <translation>Alle offenen Vorschläge dieser Art annehmen, als ein Schritt im Rückgängig-Verlauf</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="399"/>
        <source>No suggestions</source>
        <translation>Keine Vorschläge</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="402"/>
        <source>%1 pending · %2 accepted · %3 rejected</source>
        <translation>%1 offen · %2 angenommen · %3 abgelehnt</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="426"/>
        <source>Accept All %1 (%2)</source>
        <translation>Alle %1 annehmen (%2)</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="441"/>
        <source>Looking for suggestions…</source>
        <translation>Vorschläge werden gesucht…</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="444"/>
        <source>No suggestions yet.

Run Suggestions proposes node descriptions from docstrings and comments and subsystem groupings from the topic graph; with an LLM configured it also asks the model.</source>
        <translation>Noch keine Vorschläge.

„Vorschläge ermitteln“ schlägt Knotenbeschreibungen aus Docstrings und Kommentaren sowie Subsystem-Gruppierungen aus dem Topic-Graphen vor; ist ein LLM konfiguriert, wird zusätzlich das Modell gefragt.</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="448"/>
        <source>No suggestion matches the filter.</source>
        <translation>Kein Vorschlag entspricht dem Filter.</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="466"/>
        <source>Group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="468"/>
        <source>Proposal:</source>
        <translation>Vorschlag:</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="472"/>
        <source>Evidence:</source>
        <translation>Belege:</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="487"/>
        <source>Origin:</source>
        <translation>Herkunft:</translation>
    </message>
</context>
<context>
    <name>rosarch::SuggestionRunner</name>
    <message>
        <location filename="../app/suggestionrunner.cpp" line="95"/>
        <source>The suggestion run stopped with an internal error: %1</source>
        <translation>Der Vorschlagslauf wurde wegen eines internen Fehlers abgebrochen: %1</translation>
    </message>
</context>
</TS>
