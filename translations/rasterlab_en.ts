<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>AccuracyPlot</name>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="126"/>
        <source>median time per frame (ms, log scale)</source>
        <translation>median time per frame (ms, log scale)</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="132"/>
        <source>colour RMSE against the exact reference (byte steps, log scale)</source>
        <translation>colour RMSE against the exact reference (byte steps, log scale)</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="186"/>
        <source>colour: shading</source>
        <translation>colour: shading</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="195"/>
        <source>shape: rules</source>
        <translation>shape: rules</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="204"/>
        <source>filled: float; hollow: double</source>
        <translation>filled: float; hollow: double</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="207"/>
        <source>size: samples per pixel</source>
        <translation>size: samples per pixel</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="209"/>
        <source>exact reference:</source>
        <translation>exact reference:</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="211"/>
        <source>%1 ms, %2 rays</source>
        <translation>%1 ms, %2 rays</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="216"/>
        <source>an RMSE of 0 sits on the floor</source>
        <translation>an RMSE of 0 sits on the floor</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="261"/>
        <source>byte steps</source>
        <translation>byte steps</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="264"/>
        <source>coverage</source>
        <translation>coverage</translation>
    </message>
</context>
<context>
    <name>Lessons</name>
    <message>
        <location filename="../app/documents/examples.cpp" line="29"/>
        <source>One triangle</source>
        <translation>One triangle</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="30"/>
        <source>A single triangle in a 32 x 24 image, large enough to read from the back of the room. Step by pixel (Page Down, or Right and Left in presentation mode, F5) and watch the scanline fill from its left edge to its right; pick a pixel to see its barycentric coordinates, its interpolated P and N, and its Phong terms in the pixel inspector.</source>
        <translation>A single triangle in a 32 x 24 image, large enough to read from the back of the room. Step by pixel (Page Down, or Right and Left in presentation mode, F5) and watch the scanline fill from its left edge to its right; pick a pixel to see its barycentric coordinates, its interpolated P and N, and its Phong terms in the pixel inspector.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="39"/>
        <source>Two triangles that cross (the z-buffer)</source>
        <translation>Two triangles that cross (the z-buffer)</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="40"/>
        <source>Two triangles that pass through each other: each is nearer the camera over half of the other, so no order of whole triangles draws them right. It opens at the start of the frame with a breakpoint at the second triangle: Continue to Breakpoint (F8) draws the first, then step by scanline through the second and watch the z-buffer dock: its pixels are kept above the crossing line and rejected below it. Pick a pixel near the crossing to compare both depths.</source>
        <translation>Two triangles that pass through each other: each is nearer the camera over half of the other, so no order of whole triangles draws them right. It opens at the start of the frame with a breakpoint at the second triangle: Continue to Breakpoint (F8) draws the first, then step by scanline through the second and watch the z-buffer dock: its pixels are kept above the crossing line and rejected below it. Pick a pixel near the crossing to compare both depths.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="51"/>
        <source>A triangle through the near plane</source>
        <translation>A triangle through the near plane</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="52"/>
        <source>A triangle on the floor whose far corner is behind the camera. The near-plane clipping dock shows it cut at the near plane into a quad, and the quad split into two triangles. Then choose Shading &gt; Projection &gt; Plain Divide: the corner behind the eye is divided by a negative z and lands above the horizon.</source>
        <translation>A triangle on the floor whose far corner is behind the camera. The near-plane clipping dock shows it cut at the near plane into a quad, and the quad split into two triangles. Then choose Shading &gt; Projection &gt; Plain Divide: the corner behind the eye is divided by a negative z and lands above the horizon.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="60"/>
        <source>A goblet turned from a profile</source>
        <translation>A goblet turned from a profile</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="61"/>
        <source>A goblet made by turning a profile around the y axis (the course&apos;s chalice idea, 1,520 triangles of our own). Start at the camera basis dock, then follow the stages in order: view coordinates, normals, projection, scan conversion, z-buffer and lighting. Pick a pixel on the highlight of the bowl to see why it is bright.</source>
        <translation>A goblet made by turning a profile around the y axis (the course&apos;s chalice idea, 1,520 triangles of our own). Start at the camera basis dock, then follow the stages in order: view coordinates, normals, projection, scan conversion, z-buffer and lighting. Pick a pixel on the highlight of the bowl to see why it is bright.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="69"/>
        <source>A low-polygon sphere: flat, Gouraud, Phong</source>
        <translation>A low-polygon sphere: flat, Gouraud, Phong</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="70"/>
        <source>A sphere of 168 triangles. It opens in flat shading, one colour per triangle; press the Shading menu&apos;s Gouraud and then Phong to compare (File &gt; Export More &gt; Shading Side by Side puts the three in one picture). Gouraud smooths the facets but blurs the highlight; Phong draws it round.</source>
        <translation>A sphere of 168 triangles. It opens in flat shading, one colour per triangle; press the Shading menu&apos;s Gouraud and then Phong to compare (File &gt; Export More &gt; Shading Side by Side puts the three in one picture). Gouraud smooths the facets but blurs the highlight; Phong draws it round.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="78"/>
        <source>Several lights: spot, directional, attenuated</source>
        <translation>Several lights: spot, directional, attenuated</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="79"/>
        <source>A floor and a ball under three lights of the lecture slides: a yellow spot (the bright disc, with a soft edge from its exponent), a dim blue directional light from the right, and a red positional light whose strength falls with distance. Pick pixels inside and outside the spot&apos;s cone and compare the pixel inspector&apos;s terms light by light; change the lights in the Edit dock.</source>
        <translation>A floor and a ball under three lights of the lecture slides: a yellow spot (the bright disc, with a soft edge from its exponent), a dim blue directional light from the right, and a red positional light whose strength falls with distance. Pick pixels inside and outside the spot&apos;s cone and compare the pixel inspector&apos;s terms light by light; change the lights in the Edit dock.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="88"/>
        <source>Three triangles in a cycle (the painter)</source>
        <translation>Three triangles in a cycle (the painter)</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="89"/>
        <source>Three triangles that each lie in front of the next: no order of whole triangles can draw them right, so the painter&apos;s algorithm (far to near by barycentre) must fail somewhere. Step by triangle and see one painted over a nearer one; the painter&apos;s algorithm dock marks the pixels that differ from the z-buffer&apos;s image.</source>
        <translation>Three triangles that each lie in front of the next: no order of whole triangles can draw them right, so the painter&apos;s algorithm (far to near by barycentre) must fail somewhere. Step by triangle and see one painted over a nearer one; the painter&apos;s algorithm dock marks the pixels that differ from the z-buffer&apos;s image.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="97"/>
        <source>Gouraud&apos;s faults: Mach bands, a missed highlight</source>
        <translation>Gouraud&apos;s faults: Mach bands, a missed highlight</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="98"/>
        <source>Left, a coarse sphere in Gouraud shading: the brightness bends at every edge and the eye sees bands there (Mach bands). Right, a square of two triangles whose highlight falls between its corners: Gouraud lights only the corners and misses it. Switch to Phong shading and the highlight appears in the middle of the square.</source>
        <translation>Left, a coarse sphere in Gouraud shading: the brightness bends at every edge and the eye sees bands there (Mach bands). Right, a square of two triangles whose highlight falls between its corners: Gouraud lights only the corners and misses it. Switch to Phong shading and the highlight appears in the middle of the square.</translation>
    </message>
</context>
<context>
    <name>Messages</name>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="15"/>
        <source>expected the degree %1 of the Bezier surface (an integer from 1 to %2), found %3</source>
        <translation>expected the degree %1 of the Bezier surface (an integer from 1 to %2), found %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="18"/>
        <source>ignored %1 after the Bezier surface&apos;s two degrees</source>
        <translation>ignored %1 after the Bezier surface&apos;s two degrees</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="19"/>
        <source>expected the number of evaluations per direction (an integer from 2 to %1), found %2</source>
        <translation>expected the number of evaluations per direction (an integer from 2 to %1), found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="22"/>
        <source>the header declares a Bezier surface of degrees %1 x %2, so %3 control points (one a line), but only %4</source>
        <translation>the header declares a Bezier surface of degrees %1 x %2, so %3 control points (one a line), but only %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="25"/>
        <source>%1 line follows</source>
        <translation>%1 line follows</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="26"/>
        <source>%1 lines follow</source>
        <translation>%1 lines follow</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="27"/>
        <source>control point (%1, %2)</source>
        <translation>control point (%1, %2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="28"/>
        <source>ignored %1 after the %2 control points of the Bezier surface</source>
        <translation>ignored %1 after the %2 control points of the Bezier surface</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="30"/>
        <source>the header &apos;vertices triangles&apos; (two integers)</source>
        <translation>the header &apos;vertices triangles&apos; (two integers)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="31"/>
        <source>expected %1, found the end of the file</source>
        <translation>expected %1, found the end of the file</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="32"/>
        <source>this is an original Movie.BYU file (header &apos;parts vertices polygons edges&apos;), not the course&apos;s .byu format (header &apos;vertices triangles&apos;)</source>
        <translation>this is an original Movie.BYU file (header &apos;parts vertices polygons edges&apos;), not the course&apos;s .byu format (header &apos;vertices triangles&apos;)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="35"/>
        <source>vertices</source>
        <translation>vertices</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="36"/>
        <source>expected the number of triangles after the number of vertices, found the end of the line</source>
        <translation>expected the number of triangles after the number of vertices, found the end of the line</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="39"/>
        <source>triangles</source>
        <translation>triangles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="40"/>
        <source>ignored %1 after the header&apos;s two counts</source>
        <translation>ignored %1 after the header&apos;s two counts</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="41"/>
        <source>this looks like a course Bezier surface (degrees %1 x %2, %3 evaluations per direction), not a triangle mesh</source>
        <translation>this looks like a course Bezier surface (degrees %1 x %2, %3 evaluations per direction), not a triangle mesh</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="44"/>
        <source>the header declares %1 and %2 (%3), but only %4</source>
        <translation>the header declares %1 and %2 (%3), but only %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="45"/>
        <source>%1 line</source>
        <translation>%1 line</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="46"/>
        <source>%1 lines</source>
        <translation>%1 lines</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="47"/>
        <source>vertex %1 of %2</source>
        <translation>vertex %1 of %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="48"/>
        <source>triangle %1 of %2 (three vertex indices)</source>
        <translation>triangle %1 of %2 (three vertex indices)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="49"/>
        <source>expected 3 vertex indices for triangle %1 of %2, found %3</source>
        <translation>expected 3 vertex indices for triangle %1 of %2, found %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="50"/>
        <source>polygon %1 has %2 vertex indices, but only triangles (3 indices) are supported</source>
        <translation>polygon %1 has %2 vertex indices, but only triangles (3 indices) are supported</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="53"/>
        <source>expected a vertex index (a positive integer) for triangle %1, found %2</source>
        <translation>expected a vertex index (a positive integer) for triangle %1, found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="55"/>
        <source>triangle %1 refers to vertex %2, but indices are 1-based (1 to %3)</source>
        <translation>triangle %1 refers to vertex %2, but indices are 1-based (1 to %3)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="57"/>
        <source>triangle %1 refers to vertex %2, but the file declares only %3</source>
        <translation>triangle %1 refers to vertex %2, but the file declares only %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="58"/>
        <source>ignored %1 after the declared %2 and %3 (the header&apos;s counts may be wrong, or a second object follows)</source>
        <translation>ignored %1 after the declared %2 and %3 (the header&apos;s counts may be wrong, or a second object follows)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="62"/>
        <source>the camera position</source>
        <translation>the camera position</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="63"/>
        <source>the view direction</source>
        <translation>the view direction</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="64"/>
        <source>the up vector</source>
        <translation>the up vector</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="65"/>
        <source>the projection distance and half-sizes</source>
        <translation>the projection distance and half-sizes</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="66"/>
        <source>the projection distance</source>
        <translation>the projection distance</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="67"/>
        <source>the horizontal half-size of the window</source>
        <translation>the horizontal half-size of the window</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="68"/>
        <source>the vertical half-size of the window</source>
        <translation>the vertical half-size of the window</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="69"/>
        <source>the half-sizes of the window</source>
        <translation>the half-sizes of the window</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="70"/>
        <source>the light position</source>
        <translation>the light position</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="71"/>
        <source>the ambient coefficient</source>
        <translation>the ambient coefficient</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="72"/>
        <source>the ambient light colour</source>
        <translation>the ambient light colour</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="73"/>
        <source>the diffuse coefficient</source>
        <translation>the diffuse coefficient</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="74"/>
        <source>the diffuse colour of the object</source>
        <translation>the diffuse colour of the object</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="75"/>
        <source>the specular coefficient</source>
        <translation>the specular coefficient</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="76"/>
        <source>the light colour</source>
        <translation>the light colour</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="77"/>
        <source>the specular exponent</source>
        <translation>the specular exponent</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="78"/>
        <source>the number of lights</source>
        <translation>the number of lights</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="79"/>
        <source>the diffuse coefficient of each channel</source>
        <translation>the diffuse coefficient of each channel</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="80"/>
        <source>the camera&apos;s %1</source>
        <translation>the camera&apos;s %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="81"/>
        <source>the lighting&apos;s %1</source>
        <translation>the lighting&apos;s %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="82"/>
        <source>UFPE (C; N; V; d hx hy)</source>
        <translation>UFPE (C; N; V; d hx hy)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="83"/>
        <source>UFRPE (N; V; d; hx; hy; C)</source>
        <translation>UFRPE (N; V; d; hx; hy; C)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="84"/>
        <source>UFRPE (C; N; V; hx hy; d)</source>
        <translation>UFRPE (C; N; V; hx hy; d)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="85"/>
        <source>key = value</source>
        <translation>key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="86"/>
        <source>detected from the file</source>
        <translation>detected from the file</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="87"/>
        <source>UFPE (Pl; ka; Ia; kd; Od; ks; Il; n)</source>
        <translation>UFPE (Pl; ka; Ia; kd; Od; ks; Il; n)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="88"/>
        <source>UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; Il)</source>
        <translation>UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; Il)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="89"/>
        <source>UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)</source>
        <translation>UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="90"/>
        <source>a UFPE camera, C; N; V; d hx hy</source>
        <translation>a UFPE camera, C; N; V; d hx hy</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="91"/>
        <source>a UFRPE camera, N; V; d; hx; hy; C</source>
        <translation>a UFRPE camera, N; V; d; hx; hy; C</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="92"/>
        <source>a UFRPE camera, C; N; V; hx hy; d</source>
        <translation>a UFRPE camera, C; N; V; hx hy; d</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="93"/>
        <source>a key = value camera</source>
        <translation>a key = value camera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="94"/>
        <source>a camera</source>
        <translation>a camera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="95"/>
        <source>a UFPE lighting file, Pl; ka; Ia; kd; Od; ks; Il; n</source>
        <translation>a UFPE lighting file, Pl; ka; Ia; kd; Od; ks; Il; n</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="96"/>
        <source>a UFPE multi-light lighting file, ka; Ia; kd; Od; ks; n; L; L times Pl; Il</source>
        <translation>a UFPE multi-light lighting file, ka; Ia; kd; Od; ks; n; L; L times Pl; Il</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="98"/>
        <source>a UFRPE lighting file, Iamb; Ka; Il; Pl; Kd; Od; Ks; n</source>
        <translation>a UFRPE lighting file, Iamb; Ka; Il; Pl; Kd; Od; Ks; n</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="99"/>
        <source>a key = value lighting file</source>
        <translation>a key = value lighting file</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="100"/>
        <source>a lighting file</source>
        <translation>a lighting file</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="101"/>
        <source>the 1 line has %1</source>
        <translation>the 1 line has %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="102"/>
        <source>the %1 lines have %2 numbers</source>
        <translation>the %1 lines have %2 numbers</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="103"/>
        <source>line %1 has %2 where %3 needs %4</source>
        <translation>line %1 has %2 where %3 needs %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="104"/>
        <source>its last line, %1, is missing</source>
        <translation>its last line, %1, is missing</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="105"/>
        <source>line %1 is one line more</source>
        <translation>line %1 is one line more</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="106"/>
        <source>no line contains &apos;=&apos; and %1</source>
        <translation>no line contains &apos;=&apos; and %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="107"/>
        <source>%1: its first %2 lines fit this layout, and the rest is left over</source>
        <translation>%1: its first %2 lines fit this layout, and the rest is left over</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="109"/>
        <source>%1, as in that layout</source>
        <translation>%1, as in that layout</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="110"/>
        <source>%1: no layout fits exactly, and this one is one line away (%2)</source>
        <translation>%1: no layout fits exactly, and this one is one line away (%2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="111"/>
        <source>one line away from %1</source>
        <translation>one line away from %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="112"/>
        <source>an empty file</source>
        <translation>an empty file</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="113"/>
        <source>only blank lines</source>
        <translation>only blank lines</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="114"/>
        <source>1 line with %1</source>
        <translation>1 line with %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="115"/>
        <source>%1 lines with %2 numbers</source>
        <translation>%1 lines with %2 numbers</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="116"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="117"/>
        <source>lines contain &apos;=&apos;</source>
        <translation>lines contain &apos;=&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="118"/>
        <source>expected %1 or key = value, found %2 (if the layout is known, choose it by hand: --camera-format / --lighting-format, or File &gt; Course File Layouts)</source>
        <translation>expected %1 or key = value, found %2 (if the layout is known, choose it by hand: --camera-format / --lighting-format, or File &gt; Course File Layouts)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="122"/>
        <source>a camera in one of the layouts UFPE (C; N; V; d hx hy), UFRPE (N; V; d; hx; hy; C), UFRPE (C; N; V; hx hy; d)</source>
        <translation>a camera in one of the layouts UFPE (C; N; V; d hx hy), UFRPE (N; V; d; hx; hy; C), UFRPE (C; N; V; hx hy; d)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="125"/>
        <source>lighting in one of the layouts UFPE (Pl; ka; Ia; kd; Od; ks; Il; n), UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; Il), UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)</source>
        <translation>lighting in one of the layouts UFPE (Pl; ka; Ia; kd; Od; ks; Il; n), UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; Il), UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="129"/>
        <source>expected the number of lights L (a positive whole number), found %1</source>
        <translation>expected the number of lights L (a positive whole number), found %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="131"/>
        <source>L = %1 lights need twice as many lines after it (Pl and Il for each), but only %2</source>
        <translation>L = %1 lights need twice as many lines after it (Pl and Il for each), but only %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="134"/>
        <source>L = %1 lights need %2 lines after it (Pl and Il for each), but only %3</source>
        <translation>L = %1 lights need %2 lines after it (Pl and Il for each), but only %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="136"/>
        <source>%1; the layout was set to %2</source>
        <translation>%1; the layout was set to %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="137"/>
        <source>%1; the layout was set to %2, but the file looks like %3 (%4)</source>
        <translation>%1; the layout was set to %2, but the file looks like %3 (%4)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="138"/>
        <source>the layout was chosen, not detected</source>
        <translation>the layout was chosen, not detected</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="139"/>
        <source>read as %1 (%2)</source>
        <translation>read as %1 (%2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="141"/>
        <source>%1 or %2 numbers</source>
        <translation>%1 or %2 numbers</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="142"/>
        <source>%1 value</source>
        <translation>%1 value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="143"/>
        <source>%1 values</source>
        <translation>%1 values</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="144"/>
        <source>%1 vertex</source>
        <translation>%1 vertex</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="145"/>
        <source>%1 vertices</source>
        <translation>%1 vertices</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="146"/>
        <source>%1 triangle</source>
        <translation>%1 triangle</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="147"/>
        <source>%1 triangles</source>
        <translation>%1 triangles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="148"/>
        <source>%1 number</source>
        <translation>%1 number</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="149"/>
        <source>%1 numbers</source>
        <translation>%1 numbers</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="150"/>
        <source>%1 of light %2</source>
        <translation>%1 of light %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="151"/>
        <source>found %1 (separate the values with spaces, not commas)</source>
        <translation>found %1 (separate the values with spaces, not commas)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="152"/>
        <source>found %1 (the decimal separator is &apos;.&apos;)</source>
        <translation>found %1 (the decimal separator is &apos;.&apos;)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="153"/>
        <source>found %1, which is out of range</source>
        <translation>found %1, which is out of range</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="154"/>
        <source>found %1, which is not a finite number</source>
        <translation>found %1, which is not a finite number</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="155"/>
        <source>found %1</source>
        <translation>found %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="156"/>
        <source>%1 and %2</source>
        <translation>%1 and %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="157"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="158"/>
        <source>expected %1, %2 (%3), found the end of the file</source>
        <translation>expected %1, %2 (%3), found the end of the file</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="159"/>
        <source>expected a number for %1, %2</source>
        <translation>expected a number for %1, %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="160"/>
        <source>expected %1 for %2, found %3</source>
        <translation>expected %1 for %2, found %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="161"/>
        <source>ignored %1 after %2</source>
        <translation>ignored %1 after %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="162"/>
        <source>%1 = %2 is outside %3, the range the course gives for it</source>
        <translation>%1 = %2 is outside %3, the range the course gives for it</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="163"/>
        <source>%1 of light %2 = %3 is outside %4, the range the course gives for it</source>
        <translation>%1 of light %2 = %3 is outside %4, the range the course gives for it</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="165"/>
        <source>%1 = %2 is not positive: (R.V)^n then makes no highlight (it is 1 everywhere for n = 0 and grows without bound where R.V nears 0 for n &lt; 0, where the specular term is left out)</source>
        <translation>%1 = %2 is not positive: (R.V)^n then makes no highlight (it is 1 everywhere for n = 0 and grows without bound where R.V nears 0 for n &lt; 0, where the specular term is left out)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="169"/>
        <source>expected the number of %1 (a non-negative integer), found %2</source>
        <translation>expected the number of %1 (a non-negative integer), found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="170"/>
        <source>expected %1, found a comment (%2), but .byu files have no comments</source>
        <translation>expected %1, found a comment (%2), but .byu files have no comments</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="172"/>
        <source>expected a number for the %1 coordinate of %2, %3</source>
        <translation>expected a number for the %1 coordinate of %2, %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="173"/>
        <source>%1 (x y z)</source>
        <translation>%1 (x y z)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="174"/>
        <source>expected 3 coordinates for %1, found %2</source>
        <translation>expected 3 coordinates for %1, found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="175"/>
        <source>ignored extra values at the end of %1 (the first is here)</source>
        <translation>ignored extra values at the end of %1 (the first is here)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="176"/>
        <source>%1 vertex of %2 is not used by any triangle</source>
        <translation>%1 vertex of %2 is not used by any triangle</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="177"/>
        <source>%1 vertices of %2 are not used by any triangle</source>
        <translation>%1 vertices of %2 are not used by any triangle</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="178"/>
        <source>the object has no triangles</source>
        <translation>the object has no triangles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="180"/>
        <source>the light position (x y z, or x y z w: w = 0 for a directional light)</source>
        <translation>the light position (x y z, or x y z w: w = 0 for a directional light)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="182"/>
        <source>the emission of the object</source>
        <translation>the emission of the object</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="183"/>
        <source>two-sided lighting, 1 or 0</source>
        <translation>two-sided lighting, 1 or 0</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="184"/>
        <source>Blinn-Phong highlights, 1 or 0</source>
        <translation>Blinn-Phong highlights, 1 or 0</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="185"/>
        <source>the attenuation kc kl kq</source>
        <translation>the attenuation kc kl kq</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="186"/>
        <source>the spot direction</source>
        <translation>the spot direction</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="187"/>
        <source>the spot cutoff angle in degrees</source>
        <translation>the spot cutoff angle in degrees</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="188"/>
        <source>the spot exponent</source>
        <translation>the spot exponent</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="189"/>
        <source>%1; optionally %2</source>
        <translation>%1; optionally %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="190"/>
        <source>%1; optionally %2; Pl2, Il2 ... for lights 2 to %3</source>
        <translation>%1; optionally %2; Pl2, Il2 ... for lights 2 to %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="191"/>
        <source>expected &apos;key = value&apos;, found a line without &apos;=&apos; (%1 ...)</source>
        <translation>expected &apos;key = value&apos;, found a line without &apos;=&apos; (%1 ...)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="192"/>
        <source>expected &apos;key = value&apos;, found a line without &apos;=&apos; (%1)</source>
        <translation>expected &apos;key = value&apos;, found a line without &apos;=&apos; (%1)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="193"/>
        <source>expected a key before &apos;=&apos;, found nothing</source>
        <translation>expected a key before &apos;=&apos;, found nothing</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="194"/>
        <source>expected one key before &apos;=&apos;, found %1</source>
        <translation>expected one key before &apos;=&apos;, found %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="195"/>
        <source>ignored %1: the camera&apos;s axes come from N and V</source>
        <translation>ignored %1: the camera&apos;s axes come from N and V</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="196"/>
        <source>ignored the unknown key %1 (a camera has %2; a lighting file has %3)</source>
        <translation>ignored the unknown key %1 (a camera has %2; a lighting file has %3)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="198"/>
        <source>ignored the unknown key %1 (a lighting file has %2; a camera has %3)</source>
        <translation>ignored the unknown key %1 (a lighting file has %2; a camera has %3)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="200"/>
        <source>expected %1 for %2, found none</source>
        <translation>expected %1 for %2, found none</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="201"/>
        <source>expected the camera keys %1, found none of them (only lighting file keys)</source>
        <translation>expected the camera keys %1, found none of them (only lighting file keys)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="203"/>
        <source>expected the camera keys %1, found none of them</source>
        <translation>expected the camera keys %1, found none of them</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="204"/>
        <source>expected the lighting file keys %1, found none of them (only camera keys)</source>
        <translation>expected the lighting file keys %1, found none of them (only camera keys)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="206"/>
        <source>expected the lighting file keys %1, found none of them</source>
        <translation>expected the lighting file keys %1, found none of them</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="207"/>
        <source>expected a line &apos;%1 = ...&apos; (%2, %3), found no %1</source>
        <translation>expected a line &apos;%1 = ...&apos; (%2, %3), found no %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="208"/>
        <source>expected lines for %1 (a camera needs %2), found none</source>
        <translation>expected lines for %1 (a camera needs %2), found none</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="209"/>
        <source>expected lines for %1 (a lighting file needs %2), found none</source>
        <translation>expected lines for %1 (a lighting file needs %2), found none</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="210"/>
        <source>expected each key once, found %1 again (first given on line %2)</source>
        <translation>expected each key once, found %1 again (first given on line %2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="212"/>
        <source>expected light %1 (%2, %3) before light %4, found %5 (lights are numbered without gaps)</source>
        <translation>expected light %1 (%2, %3) before light %4, found %5 (lights are numbered without gaps)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="215"/>
        <source>expected a line &apos;%1 = ...&apos; (%2 of light %3), found %4 without it</source>
        <translation>expected a line &apos;%1 = ...&apos; (%2 of light %3), found %4 without it</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="217"/>
        <source>expected 1 or 0 for %1, found %2</source>
        <translation>expected 1 or 0 for %1, found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="218"/>
        <source>expected %1 coefficients of 0 or more (kc kl kq), found %2</source>
        <translation>expected %1 coefficients of 0 or more (kc kl kq), found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="219"/>
        <source>expected %1 with a coefficient above 0, found 0 0 0 (1 / 0 light)</source>
        <translation>expected %1 with a coefficient above 0, found 0 0 0 (1 / 0 light)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="221"/>
        <source>%1 has no effect: a directional light (w = 0) is not attenuated</source>
        <translation>%1 has no effect: a directional light (w = 0) is not attenuated</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="223"/>
        <source>expected a spot direction other than 0 0 0 for %1</source>
        <translation>expected a spot direction other than 0 0 0 for %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="224"/>
        <source>expected %1 from 0 to 90 degrees, or 180 (not a spot), found %2</source>
        <translation>expected %1 from 0 to 90 degrees, or 180 (not a spot), found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="226"/>
        <source>%1: no %2, the spot points along -z (OpenGL&apos;s default)</source>
        <translation>%1: no %2, the spot points along -z (OpenGL&apos;s default)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="227"/>
        <source>expected %1 from 0 to 128, found %2</source>
        <translation>expected %1 from 0 to 128, found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="228"/>
        <source>light %1 is not a spot without %2 (0 to 90 degrees): its spot direction and exponent are unused</source>
        <translation>light %1 is not a spot without %2 (0 to 90 degrees): its spot direction and exponent are unused</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="232"/>
        <source>read as an original Movie.BYU file (the header has four integers: parts, vertices, polygons, edges): %1, fan-triangulated into %2</source>
        <translation>read as an original Movie.BYU file (the header has four integers: parts, vertices, polygons, edges): %1, fan-triangulated into %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="235"/>
        <source>read as a course Bezier surface (the header &apos;m n&apos; is followed by a line of one number, the evaluations per direction): degrees %1 x %2, evaluated on a %3 x %3 grid into %4 and %5</source>
        <translation>read as a course Bezier surface (the header &apos;m n&apos; is followed by a line of one number, the evaluations per direction): degrees %1 x %2, evaluated on a %3 x %3 grid into %4 and %5</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="240"/>
        <source>cannot write the camera: its values must be finite numbers (a course file cannot hold nan or inf)</source>
        <translation>cannot write the camera: its values must be finite numbers (a course file cannot hold nan or inf)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="243"/>
        <source>cannot write a camera in the layout &apos;auto&apos;: choose UFPE, UFRPE or key = value</source>
        <translation>cannot write a camera in the layout &apos;auto&apos;: choose UFPE, UFRPE or key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="246"/>
        <source>an emission (Ke)</source>
        <translation>an emission (Ke)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="247"/>
        <source>one-sided lighting</source>
        <translation>one-sided lighting</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="248"/>
        <source>Blinn-Phong highlights</source>
        <translation>Blinn-Phong highlights</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="249"/>
        <source>a directional light (w = 0)</source>
        <translation>a directional light (w = 0)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="250"/>
        <source>an attenuated light</source>
        <translation>an attenuated light</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="251"/>
        <source>a spot light</source>
        <translation>a spot light</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="252"/>
        <source>cannot write lighting in the layout &apos;auto&apos;: choose UFPE, UFPE multi-light, UFRPE or key = value</source>
        <translation>cannot write lighting in the layout &apos;auto&apos;: choose UFPE, UFPE multi-light, UFRPE or key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="255"/>
        <source>cannot write %1 light in the layout %2, which holds exactly one: choose the UFPE multi-light layout or key = value</source>
        <translation>cannot write %1 light in the layout %2, which holds exactly one: choose the UFPE multi-light layout or key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="258"/>
        <source>cannot write %1 lights in the layout %2, which holds exactly one: choose the UFPE multi-light layout or key = value</source>
        <translation>cannot write %1 lights in the layout %2, which holds exactly one: choose the UFPE multi-light layout or key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="261"/>
        <source>cannot write lighting without lights: the UFPE multi-light and key = value layouts hold one light or more</source>
        <translation>cannot write lighting without lights: the UFPE multi-light and key = value layouts hold one light or more</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="264"/>
        <source>cannot write %1 lights in a key = value file, which holds %2 at most (Pl to %3)</source>
        <translation>cannot write %1 lights in a key = value file, which holds %2 at most (Pl to %3)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="267"/>
        <source>cannot write %1 in the layout %2, which holds the course&apos;s point lights only: choose key = value</source>
        <translation>cannot write %1 in the layout %2, which holds the course&apos;s point lights only: choose key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="270"/>
        <source>cannot write the lighting: its values must be finite numbers (a course file cannot hold nan or inf)</source>
        <translation>cannot write the lighting: its values must be finite numbers (a course file cannot hold nan or inf)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="273"/>
        <source>cannot write lighting in the layout &apos;auto&apos;</source>
        <translation>cannot write lighting in the layout &apos;auto&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="275"/>
        <source>%1 argument</source>
        <translation>%1 argument</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="276"/>
        <source>%1 arguments</source>
        <translation>%1 arguments</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="277"/>
        <source>skipped %1 line with the unknown command &apos;%2&apos;</source>
        <translation>skipped %1 line with the unknown command &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="278"/>
        <source>skipped %1 lines with the unknown command &apos;%2&apos;</source>
        <translation>skipped %1 lines with the unknown command &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="279"/>
        <source>expected a &apos;png width height file&apos; command, found none</source>
        <translation>expected a &apos;png width height file&apos; command, found none</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="280"/>
        <source>expected %1 number after &apos;%2&apos; (%3), found %4</source>
        <translation>expected %1 number after &apos;%2&apos; (%3), found %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="281"/>
        <source>expected %1 numbers after &apos;%2&apos; (%3), found %4</source>
        <translation>expected %1 numbers after &apos;%2&apos; (%3), found %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="282"/>
        <source>expected a number in &apos;%1&apos; (%2), found %3</source>
        <translation>expected a number in &apos;%1&apos; (%2), found %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="283"/>
        <source>ignored %1 value after &apos;%2&apos;</source>
        <translation>ignored %1 value after &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="284"/>
        <source>ignored %1 values after &apos;%2&apos;</source>
        <translation>ignored %1 values after &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="285"/>
        <source>expected a vertex index in &apos;%1&apos;, found %2</source>
        <translation>expected a vertex index in &apos;%1&apos;, found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="286"/>
        <source>&apos;%1&apos; refers to vertex %2, but indices start at 1 (or count back from -1, the last)</source>
        <translation>&apos;%1&apos; refers to vertex %2, but indices start at 1 (or count back from -1, the last)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="289"/>
        <source>&apos;%2&apos; refers to vertex %3, but only %1 vertex is defined so far</source>
        <translation>&apos;%2&apos; refers to vertex %3, but only %1 vertex is defined so far</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="290"/>
        <source>&apos;%2&apos; refers to vertex %3, but only %1 vertices are defined so far</source>
        <translation>&apos;%2&apos; refers to vertex %3, but only %1 vertices are defined so far</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="292"/>
        <source>expected %1 vertex index in &apos;%2&apos; (%3), found %4</source>
        <translation>expected %1 vertex index in &apos;%2&apos; (%3), found %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="293"/>
        <source>expected %1 vertex indices in &apos;%2&apos; (%3), found %4</source>
        <translation>expected %1 vertex indices in &apos;%2&apos; (%3), found %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="294"/>
        <source>expected the number of subdivisions after &apos;%1&apos;, found the end of the line</source>
        <translation>expected the number of subdivisions after &apos;%1&apos;, found the end of the line</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="296"/>
        <source>expected the number of subdivisions (a whole number from 1 to 10) after &apos;%1&apos;, found %2</source>
        <translation>expected the number of subdivisions (a whole number from 1 to 10) after &apos;%1&apos;, found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="299"/>
        <source>expected a &apos;png width height file&apos; command before &apos;%1&apos;</source>
        <translation>expected a &apos;png width height file&apos; command before &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="300"/>
        <source>this command would bring the file to %1 triangles, more than the limit of %2 a command file may draw</source>
        <translation>this command would bring the file to %1 triangles, more than the limit of %2 a command file may draw</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="303"/>
        <source>expected &apos;png width height file&apos;, found %1</source>
        <translation>expected &apos;png width height file&apos;, found %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="304"/>
        <source>expected the image width (a whole number from 1 to 65536), found %1</source>
        <translation>expected the image width (a whole number from 1 to 65536), found %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="306"/>
        <source>expected the image height (a whole number from 1 to 65536), found %1</source>
        <translation>expected the image height (a whole number from 1 to 65536), found %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="308"/>
        <source>expected an image file name after &apos;png width height&apos;, found %1</source>
        <translation>expected an image file name after &apos;png width height&apos;, found %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="309"/>
        <source>the image name %1 reaches into folders: it is written as %2 in the output folder</source>
        <translation>the image name %1 reaches into folders: it is written as %2 in the output folder</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="312"/>
        <source>an earlier png command (line %1) names %2 too: this image replaces it</source>
        <translation>an earlier png command (line %1) names %2 too: this image replaces it</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="314"/>
        <source>x y z w</source>
        <translation>x y z w</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="315"/>
        <source>x y z</source>
        <translation>x y z</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="316"/>
        <source>r g b</source>
        <translation>r g b</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="317"/>
        <source>s t</source>
        <translation>s t</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="318"/>
        <source>i1 i2 i3</source>
        <translation>i1 i2 i3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="319"/>
        <source>&apos;trit&apos; needs a texture: expected a &apos;texture file.png&apos; command before it</source>
        <translation>&apos;trit&apos; needs a texture: expected a &apos;texture file.png&apos; command before it</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="321"/>
        <source>subd i1 ... i16</source>
        <translation>subd i1 ... i16</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="322"/>
        <source>subd i1 ... i10</source>
        <translation>subd i1 ... i10</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="323"/>
        <source>a11 a12 ... a44, row by row</source>
        <translation>a11 a12 ... a44, row by row</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="324"/>
        <source>l r b t n f</source>
        <translation>l r b t n f</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="325"/>
        <source>&apos;%1&apos; needs l != r, b != t and n != f, found %2 %3 %4 %5 %6 %7</source>
        <translation>&apos;%1&apos; needs l != r, b != t and n != f, found %2 %3 %4 %5 %6 %7</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="326"/>
        <source>dx dy dz</source>
        <translation>dx dy dz</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="327"/>
        <source>sx sy sz</source>
        <translation>sx sy sz</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="328"/>
        <source>degrees</source>
        <translation>degrees</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="329"/>
        <source>degrees x y z</source>
        <translation>degrees x y z</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="330"/>
        <source>&apos;rotate&apos; needs an axis, found the zero vector</source>
        <translation>&apos;rotate&apos; needs an axis, found the zero vector</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="331"/>
        <source>eye center upx upy upz</source>
        <translation>eye center upx upy upz</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="332"/>
        <source>expected &apos;lookat eye center upx upy upz&apos;, found %1</source>
        <translation>expected &apos;lookat eye center upx upy upz&apos;, found %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="333"/>
        <source>expected a number in &apos;lookat&apos; (eye center upx upy upz), found %1</source>
        <translation>expected a number in &apos;lookat&apos; (eye center upx upy upz), found %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="335"/>
        <source>&apos;lookat&apos; needs an eye apart from the center and an up that is not along the line of sight</source>
        <translation>&apos;lookat&apos; needs an eye apart from the center and an up that is not along the line of sight</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="338"/>
        <source>p1 p2 p3 p4</source>
        <translation>p1 p2 p3 p4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="339"/>
        <source>expected a file name after &apos;texture&apos;, found the end of the line</source>
        <translation>expected a file name after &apos;texture&apos;, found the end of the line</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="341"/>
        <source>lx ly lz</source>
        <translation>lx ly lz</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="342"/>
        <source>&apos;sunlight&apos; needs a direction, found the zero vector</source>
        <translation>&apos;sunlight&apos; needs a direction, found the zero vector</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="343"/>
        <source>i1</source>
        <translation>i1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="344"/>
        <source>alpha</source>
        <translation>alpha</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="346"/>
        <source>parts</source>
        <translation>parts</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="347"/>
        <source>polygons</source>
        <translation>polygons</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="348"/>
        <source>polygon indices (edges)</source>
        <translation>polygon indices (edges)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="349"/>
        <source>%1 part</source>
        <translation>%1 part</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="350"/>
        <source>%1 parts</source>
        <translation>%1 parts</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="351"/>
        <source>%1 polygon</source>
        <translation>%1 polygon</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="352"/>
        <source>%1 polygons</source>
        <translation>%1 polygons</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="353"/>
        <source>%1 polygon index</source>
        <translation>%1 polygon index</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="354"/>
        <source>%1 polygon indices</source>
        <translation>%1 polygon indices</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="355"/>
        <source>%1, %2 and %3</source>
        <translation>%1, %2 and %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="356"/>
        <source>the header declares %1 (%2: 2 a part, 3 a vertex, 1 an index), but only %3</source>
        <translation>the header declares %1 (%2: 2 a part, 3 a vertex, 1 an index), but only %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="358"/>
        <source>more numbers than a file can hold</source>
        <translation>more numbers than a file can hold</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="359"/>
        <source>%1 number follows</source>
        <translation>%1 number follows</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="360"/>
        <source>%1 numbers follow</source>
        <translation>%1 numbers follow</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="361"/>
        <source>the header declares %1 but only %2, fewer than the 3 each polygon needs</source>
        <translation>the header declares %1 but only %2, fewer than the 3 each polygon needs</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="363"/>
        <source>the first polygon of part %1</source>
        <translation>the first polygon of part %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="364"/>
        <source>the last polygon of part %1</source>
        <translation>the last polygon of part %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="365"/>
        <source>expected %1 (a positive integer), found %2</source>
        <translation>expected %1 (a positive integer), found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="366"/>
        <source>expected the polygon range of part %1 within 1 to %2, first &lt;= last, found %3 to %4</source>
        <translation>expected the polygon range of part %1 within 1 to %2, first &lt;= last, found %3 to %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="369"/>
        <source>an index of polygon %1</source>
        <translation>an index of polygon %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="370"/>
        <source>expected a vertex index (a non-zero integer, negated at the end of a polygon) for polygon %1, found %2</source>
        <translation>expected a vertex index (a non-zero integer, negated at the end of a polygon) for polygon %1, found %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="373"/>
        <source>polygon %1 starts here, but the header declares only %2</source>
        <translation>polygon %1 starts here, but the header declares only %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="374"/>
        <source>polygon %1 refers to vertex 0, but indices are 1-based (1 to %2)</source>
        <translation>polygon %1 refers to vertex 0, but indices are 1-based (1 to %2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="376"/>
        <source>polygon %1 refers to vertex %2, but the file declares only %3</source>
        <translation>polygon %1 refers to vertex %2, but the file declares only %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="377"/>
        <source>polygon %1 has %2, but a polygon needs at least 3</source>
        <translation>polygon %1 has %2, but a polygon needs at least 3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="378"/>
        <source>expected the last index of polygon %1 to be negative (it ends the polygon), found the end of the header&apos;s %2</source>
        <translation>expected the last index of polygon %1 to be negative (it ends the polygon), found the end of the header&apos;s %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="381"/>
        <source>the header declares %1, but its %2 end only %3</source>
        <translation>the header declares %1, but its %2 end only %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="382"/>
        <source>ignored %1 after the declared %2 (the header&apos;s counts may be wrong, or a second object follows)</source>
        <translation>ignored %1 after the declared %2 (the header&apos;s counts may be wrong, or a second object follows)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="386"/>
        <source>the camera&apos;s C, N and V must be finite numbers</source>
        <translation>the camera&apos;s C, N and V must be finite numbers</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="387"/>
        <source>N, the view direction, is the zero vector: it must point from the camera toward the scene</source>
        <translation>N, the view direction, is the zero vector: it must point from the camera toward the scene</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="390"/>
        <source>V, the up vector, is the zero vector: it must say which way is up</source>
        <translation>V, the up vector, is the zero vector: it must say which way is up</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="392"/>
        <source>d, the distance to the projection plane, is 0: the projection (d/hx) x/z would squash every point to the centre</source>
        <translation>d, the distance to the projection plane, is 0: the projection (d/hx) x/z would squash every point to the centre</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="395"/>
        <source>hx, the horizontal half-size of the window, is 0: the projection (d/hx) x/z divides by it</source>
        <translation>hx, the horizontal half-size of the window, is 0: the projection (d/hx) x/z divides by it</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="398"/>
        <source>hy, the vertical half-size of the window, is 0: the projection (d/hy) y/z divides by it</source>
        <translation>hy, the vertical half-size of the window, is 0: the projection (d/hy) y/z divides by it</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="401"/>
        <source>V %1 is parallel to N %2: Gram-Schmidt leaves nothing of V, so &apos;up&apos; is undefined; choose a V that is not along N</source>
        <translation>V %1 is parallel to N %2: Gram-Schmidt leaves nothing of V, so &apos;up&apos; is undefined; choose a V that is not along N</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="404"/>
        <source>hx is negative: the image is mirrored left to right</source>
        <translation>hx is negative: the image is mirrored left to right</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="405"/>
        <source>hy is negative: the image is mirrored top to bottom</source>
        <translation>hy is negative: the image is mirrored top to bottom</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="406"/>
        <source>d is negative: the image is turned upside down and mirrored</source>
        <translation>d is negative: the image is turned upside down and mirrored</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="408"/>
        <source>the near plane z = %1 and the clip planes</source>
        <translation>the near plane z = %1 and the clip planes</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="409"/>
        <source>the near plane z = %1</source>
        <translation>the near plane z = %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="410"/>
        <source>%1 lies wholly behind the near plane</source>
        <translation>%1 lies wholly behind the near plane</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="411"/>
        <source>%1 lie wholly behind the near plane</source>
        <translation>%1 lie wholly behind the near plane</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="412"/>
        <source>%1 and %2 wholly outside a clip plane</source>
        <translation>%1 and %2 wholly outside a clip plane</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="413"/>
        <source>the clip planes or the guard band 2^28 pixels around the image</source>
        <translation>the clip planes or the guard band 2^28 pixels around the image</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="414"/>
        <source>the guard band 2^28 pixels around the image</source>
        <translation>the guard band 2^28 pixels around the image</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="415"/>
        <source>%1 lie wholly outside a clip plane</source>
        <translation>%1 lie wholly outside a clip plane</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="416"/>
        <source>%1 triangle was clipped against %2</source>
        <translation>%1 triangle was clipped against %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="417"/>
        <source>%1 triangles were clipped against %2</source>
        <translation>%1 triangles were clipped against %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="418"/>
        <source>%1; %2, not drawn</source>
        <translation>%1; %2, not drawn</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="419"/>
        <source>every triangle is behind the camera (is N pointing away from the object?): the image is empty</source>
        <translation>every triangle is behind the camera (is N pointing away from the object?): the image is empty</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="422"/>
        <source>%1. The plain divide of seed 000, x/z and y/z with z &lt; 0, would draw it: the object&apos;s point reflection through the eye (turned half a turn on the screen), where the z-buffer, keeping the smallest z, keeps the side farthest from the camera</source>
        <translation>%1. The plain divide of seed 000, x/z and y/z with z &lt; 0, would draw it: the object&apos;s point reflection through the eye (turned half a turn on the screen), where the z-buffer, keeping the smallest z, keeps the side farthest from the camera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="427"/>
        <source>%1. The plain divide of seed 000, x/z and y/z with z &lt; 0, would draw all %2 of them: the object&apos;s point reflection through the eye (turned half a turn on the screen), where the z-buffer, keeping the smallest z, keeps the side farthest from the camera</source>
        <translation>%1. The plain divide of seed 000, x/z and y/z with z &lt; 0, would draw all %2 of them: the object&apos;s point reflection through the eye (turned half a turn on the screen), where the z-buffer, keeping the smallest z, keeps the side farthest from the camera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="432"/>
        <source>%1. The plain divide of seed 000, x/z and y/z with z &lt; 0, would draw %2 of them: the object&apos;s point reflection through the eye (turned half a turn on the screen), where the z-buffer, keeping the smallest z, keeps the side farthest from the camera</source>
        <translation>%1. The plain divide of seed 000, x/z and y/z with z &lt; 0, would draw %2 of them: the object&apos;s point reflection through the eye (turned half a turn on the screen), where the z-buffer, keeping the smallest z, keeps the side farthest from the camera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="437"/>
        <source>plain divide: %1 triangle reaches from in front of the eye to at or behind it (w of different signs, or 0): divided by w without clipping, it wraps through infinity and is drawn wrong (clipping at the near plane draws its front part)</source>
        <translation>plain divide: %1 triangle reaches from in front of the eye to at or behind it (w of different signs, or 0): divided by w without clipping, it wraps through infinity and is drawn wrong (clipping at the near plane draws its front part)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="442"/>
        <source>plain divide: %1 triangles reach from in front of the eye to at or behind it (w of different signs, or 0): divided by w without clipping, it wraps through infinity and is drawn wrong (clipping at the near plane draws its front part)</source>
        <translation>plain divide: %1 triangles reach from in front of the eye to at or behind it (w of different signs, or 0): divided by w without clipping, it wraps through infinity and is drawn wrong (clipping at the near plane draws its front part)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="447"/>
        <source>%1 vertices project more than 2^28 pixels from the image and were pulled in to that distance: triangles through them may be distorted on screen</source>
        <translation>%1 vertices project more than 2^28 pixels from the image and were pulled in to that distance: triangles through them may be distorted on screen</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="450"/>
        <source>%1 triangles project to infinite or undefined coordinates and were not drawn</source>
        <translation>%1 triangles project to infinite or undefined coordinates and were not drawn</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="453"/>
        <source>%1 triangle faces away from the camera on a closed surface seen from outside: hidden, so not drawn (back-face culling)</source>
        <translation>%1 triangle faces away from the camera on a closed surface seen from outside: hidden, so not drawn (back-face culling)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="456"/>
        <source>%1 triangles face away from the camera on a closed surface seen from outside: hidden, so not drawn (back-face culling)</source>
        <translation>%1 triangles face away from the camera on a closed surface seen from outside: hidden, so not drawn (back-face culling)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="459"/>
        <source>%1 triangle is clockwise on screen and culled</source>
        <translation>%1 triangle is clockwise on screen and culled</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="460"/>
        <source>%1 triangles are clockwise on screen and culled</source>
        <translation>%1 triangles are clockwise on screen and culled</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="461"/>
        <source>%1 triangle reaches from in front of the eye to at or behind it (w of different signs): only the part with w &gt;= %2 is drawn</source>
        <translation>%1 triangle reaches from in front of the eye to at or behind it (w of different signs): only the part with w &gt;= %2 is drawn</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="464"/>
        <source>%1 triangles reach from in front of the eye to at or behind it (w of different signs): only the part with w &gt;= %2 is drawn</source>
        <translation>%1 triangles reach from in front of the eye to at or behind it (w of different signs): only the part with w &gt;= %2 is drawn</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="467"/>
        <source>plain divide: %1 triangle lies wholly behind the eye (w &lt; 0), drawn without clipping as the point reflection through the eye</source>
        <translation>plain divide: %1 triangle lies wholly behind the eye (w &lt; 0), drawn without clipping as the point reflection through the eye</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="470"/>
        <source>plain divide: %1 triangles lie wholly behind the eye (w &lt; 0), drawn without clipping as the point reflection through the eye</source>
        <translation>plain divide: %1 triangles lie wholly behind the eye (w &lt; 0), drawn without clipping as the point reflection through the eye</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="474"/>
        <source>no scene to render</source>
        <translation>no scene to render</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="475"/>
        <source>the image size %1x%2 is empty</source>
        <translation>the image size %1x%2 is empty</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="476"/>
        <source>no triangle covers a pixel: all %1 triangles in front of the camera project outside the image (check N, d, hx and hy)</source>
        <translation>no triangle covers a pixel: all %1 triangles in front of the camera project outside the image (check N, d, hx and hy)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="479"/>
        <source>%1 triangles have zero area and no normal</source>
        <translation>%1 triangles have zero area and no normal</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="481"/>
        <source>no frame to step through</source>
        <translation>no frame to step through</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="482"/>
        <source>stepping keeps at most %1 fragments, and this frame has %2: the final image and the views still work</source>
        <translation>stepping keeps at most %1 fragments, and this frame has %2: the final image and the views still work</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="485"/>
        <source>cancelled</source>
        <translation>cancelled</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="486"/>
        <source>internal error: the rows hold %1 pixels and the depth test saw %2 fragments</source>
        <translation>internal error: the rows hold %1 pixels and the depth test saw %2 fragments</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="490"/>
        <source>light %1 is %2 above triangle %3 of %4, nearer than float can resolve points there (%5): the pixels under it may be lit from the wrong side</source>
        <translation>light %1 is %2 above triangle %3 of %4, nearer than float can resolve points there (%5): the pixels under it may be lit from the wrong side</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="494"/>
        <source>measurement cancelled</source>
        <translation>measurement cancelled</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="495"/>
        <source>supersampling must be 1 to 16 samples per axis</source>
        <translation>supersampling must be 1 to 16 samples per axis</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="497"/>
        <source>the scene has no light to move</source>
        <translation>the scene has no light to move</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="498"/>
        <source>no triangle is in front of the camera</source>
        <translation>no triangle is in front of the camera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="500"/>
        <source>the exact reference handles course scenes (the course camera, view z as depth, the course&apos;s Phong lighting with the material&apos;s colour); %1</source>
        <translation>the exact reference handles course scenes (the course camera, view z as depth, the course&apos;s Phong lighting with the material&apos;s colour); %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="503"/>
        <source>this scene has no course camera</source>
        <translation>this scene has no course camera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="504"/>
        <source>this scene&apos;s depth is NDC z</source>
        <translation>this scene&apos;s depth is NDC z</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="505"/>
        <source>%1 has its own projection matrix</source>
        <translation>%1 has its own projection matrix</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="506"/>
        <source>%1 is not lit by the course&apos;s Phong model</source>
        <translation>%1 is not lit by the course&apos;s Phong model</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="507"/>
        <source>%1 takes its colour from its vertices or a texture</source>
        <translation>%1 takes its colour from its vertices or a texture</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="508"/>
        <source>%1 is lit with flat normals</source>
        <translation>%1 is lit with flat normals</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="509"/>
        <source>samples per axis must be 1 to 16</source>
        <translation>samples per axis must be 1 to 16</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="511"/>
        <source>(%1, %2, %3, %4)</source>
        <translation>(%1, %2, %3, %4)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="512"/>
        <source>the ambient term multiplied by the object colour: Ia*ka*Od instead of Ia*ka</source>
        <translation>the ambient term multiplied by the object colour: Ia*ka*Od instead of Ia*ka</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="515"/>
        <source>the normal not turned toward the viewer where V.N &lt; 0</source>
        <translation>the normal not turned toward the viewer where V.N &lt; 0</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="516"/>
        <source>specular added where R.V &lt; 0 (no check before (R.V)^n)</source>
        <translation>specular added where R.V &lt; 0 (no check before (R.V)^n)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="517"/>
        <source>diffuse and specular computed where N.L &lt; 0 (the light is behind the surface)</source>
        <translation>diffuse and specular computed where N.L &lt; 0 (the light is behind the surface)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="520"/>
        <source>the interpolated normal not normalised</source>
        <translation>the interpolated normal not normalised</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="521"/>
        <source>%1 shading where another model was asked</source>
        <translation>%1 shading where another model was asked</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="522"/>
        <source>%1 shading where %2 was asked</source>
        <translation>%1 shading where %2 was asked</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="523"/>
        <source>the image mirrored left-right (x runs the other way)</source>
        <translation>the image mirrored left-right (x runs the other way)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="524"/>
        <source>the image upside down (row 0 at the bottom: y not flipped)</source>
        <translation>the image upside down (row 0 at the bottom: y not flipped)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="525"/>
        <source>the image shifted by one pixel: (%1, %2)</source>
        <translation>the image shifted by one pixel: (%1, %2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="526"/>
        <source>%1; pixels covered by one side only: %2 as ours is, %3 with ours carried by the map</source>
        <translation>%1; pixels covered by one side only: %2 as ours is, %3 with ours carried by the map</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="527"/>
        <source>check the screen formulas, x = (x_ndc + 1) * width / 2 and y = (1 - y_ndc) * height / 2, each with its own size, and that pixel (x, y) is written at column x of row y</source>
        <translation>check the screen formulas, x = (x_ndc + 1) * width / 2 and y = (1 - y_ndc) * height / 2, each with its own size, and that pixel (x, y) is written at column x of row y</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="528"/>
        <source>its centre moved by (%1, %2) pixels</source>
        <translation>its centre moved by (%1, %2) pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="529"/>
        <source>mirrored left-right</source>
        <translation>mirrored left-right</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="530"/>
        <source>comparison cancelled</source>
        <translation>comparison cancelled</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="531"/>
        <source>the vertex normals summed over every vertex at the same position instead of by the vertex&apos;s index (a faceted mesh drawn smooth)</source>
        <translation>the vertex normals summed over every vertex at the same position instead of by the vertex&apos;s index (a faceted mesh drawn smooth)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="532"/>
        <source>seed 000: a vertex&apos;s normal sums the normals of the triangles that use that vertex, by its index; vertices repeated at one position keep their own</source>
        <translation>seed 000: a vertex&apos;s normal sums the normals of the triangles that use that vertex, by its index; vertices repeated at one position keep their own</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="533"/>
        <source>our image carried by that map of the screen (each pixel from the nearest of ours) gives their pixels</source>
        <translation>our image carried by that map of the screen (each pixel from the nearest of ours) gives their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="534"/>
        <source>stretched %1 times across</source>
        <translation>stretched %1 times across</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="535"/>
        <source>stretched %1 times across and %2 times up and down</source>
        <translation>stretched %1 times across and %2 times up and down</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="536"/>
        <source>stretched %1 times up and down</source>
        <translation>stretched %1 times up and down</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="537"/>
        <source>the ratio of the image&apos;s sides (one size used for both axes)</source>
        <translation>the ratio of the image&apos;s sides (one size used for both axes)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="538"/>
        <source>the screen mapped another way: theirs is ours %1 (x&apos; = %2 x + %3 y + %4, y&apos; = %5 x + %6 y + %7)</source>
        <translation>the screen mapped another way: theirs is ours %1 (x&apos; = %2 x + %3 y + %4, y&apos; = %5 x + %6 y + %7)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="539"/>
        <source>turned %1 degrees clockwise</source>
        <translation>turned %1 degrees clockwise</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="540"/>
        <source>turned %1 degrees counter-clockwise</source>
        <translation>turned %1 degrees counter-clockwise</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="541"/>
        <source>turned 90 degrees clockwise</source>
        <translation>turned 90 degrees clockwise</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="542"/>
        <source>turned 90 degrees counter-clockwise</source>
        <translation>turned 90 degrees counter-clockwise</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="543"/>
        <source>upside down</source>
        <translation>upside down</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="544"/>
        <source>x and y swapped (transposed)</source>
        <translation>x and y swapped (transposed)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="545"/>
        <source>x and y swapped and both mirrored</source>
        <translation>x and y swapped and both mirrored</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="546"/>
        <source>pixels sampled at their centres (x + 0.5) instead of their corners</source>
        <translation>pixels sampled at their centres (x + 0.5) instead of their corners</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="548"/>
        <source>pixels sampled at their corners instead of their centres (x + 0.5)</source>
        <translation>pixels sampled at their corners instead of their centres (x + 0.5)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="550"/>
        <source>vertex positions rounded instead of truncated to whole pixels</source>
        <translation>vertex positions rounded instead of truncated to whole pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="551"/>
        <source>vertex positions kept fractional (never made whole) instead of truncated to whole pixels</source>
        <translation>vertex positions kept fractional (never made whole) instead of truncated to whole pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="553"/>
        <source>vertex positions truncated instead of rounded to whole pixels</source>
        <translation>vertex positions truncated instead of rounded to whole pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="554"/>
        <source>vertex positions rounded instead of truncated to the sub-pixel grid</source>
        <translation>vertex positions rounded instead of truncated to the sub-pixel grid</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="556"/>
        <source>vertex positions truncated instead of rounded to the sub-pixel grid</source>
        <translation>vertex positions truncated instead of rounded to the sub-pixel grid</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="558"/>
        <source>vertex positions truncated to the sub-pixel grid instead of kept as computed</source>
        <translation>vertex positions truncated to the sub-pixel grid instead of kept as computed</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="560"/>
        <source>the top-left fill rule where edges are inclusive</source>
        <translation>the top-left fill rule where edges are inclusive</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="561"/>
        <source>inclusive edges where the fill rule is top-left</source>
        <translation>inclusive edges where the fill rule is top-left</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="562"/>
        <source>colour bytes rounded instead of truncated (off by one)</source>
        <translation>colour bytes rounded instead of truncated (off by one)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="563"/>
        <source>colour bytes truncated instead of rounded (off by one)</source>
        <translation>colour bytes truncated instead of rounded (off by one)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="564"/>
        <source>colours above 255 wrap around instead of clamping</source>
        <translation>colours above 255 wrap around instead of clamping</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="565"/>
        <source>the painter&apos;s order (far to near, no depth test) instead of the z-buffer</source>
        <translation>the painter&apos;s order (far to near, no depth test) instead of the z-buffer</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="567"/>
        <source>z &lt; stored instead of z &lt;= stored in the depth test (ties keep the earlier triangle)</source>
        <translation>z &lt; stored instead of z &lt;= stored in the depth test (ties keep the earlier triangle)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="570"/>
        <source>z &lt;= stored instead of z &lt; stored in the depth test (ties go to the later triangle)</source>
        <translation>z &lt;= stored instead of z &lt; stored in the depth test (ties go to the later triangle)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="573"/>
        <source>a different background: %1 where the scene&apos;s is %2</source>
        <translation>a different background: %1 where the scene&apos;s is %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="574"/>
        <source>alpha %1 on covered pixels instead of 255</source>
        <translation>alpha %1 on covered pixels instead of 255</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="575"/>
        <source>our pixels lit again with that formula (the same triangles, barycentrics, P&apos;, N, lights and material) give theirs</source>
        <translation>our pixels lit again with that formula (the same triangles, barycentrics, P&apos;, N, lights and material) give theirs</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="578"/>
        <source>the scene rendered again in that shading model gives their pixels</source>
        <translation>the scene rendered again in that shading model gives their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="580"/>
        <source>our image moved that way gives their pixels</source>
        <translation>our image moved that way gives their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="581"/>
        <source>the scene rendered again with that rule gives their pixels</source>
        <translation>the scene rendered again with that rule gives their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="582"/>
        <source>our float colours made bytes that way give their pixels</source>
        <translation>our float colours made bytes that way give their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="583"/>
        <source>the scene painted far to near without a depth test gives their pixels</source>
        <translation>the scene painted far to near without a depth test gives their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="585"/>
        <source>their pixels where no triangle of ours is take that colour</source>
        <translation>their pixels where no triangle of ours is take that colour</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="586"/>
        <source>their pixels where a triangle of ours is take that alpha</source>
        <translation>their pixels where a triangle of ours is take that alpha</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="587"/>
        <source>seed 000&apos;s ambient term is Ia*ka, without the object colour Od</source>
        <translation>seed 000&apos;s ambient term is Ia*ka, without the object colour Od</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="588"/>
        <source>seed 000: if V.N &lt; 0, N := -N before the lighting</source>
        <translation>seed 000: if V.N &lt; 0, N := -N before the lighting</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="589"/>
        <source>seed 000: if R.V &lt; 0, no specular term</source>
        <translation>seed 000: if R.V &lt; 0, no specular term</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="590"/>
        <source>seed 000: if N.L &lt; 0, neither diffuse nor specular</source>
        <translation>seed 000: if N.L &lt; 0, neither diffuse nor specular</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="591"/>
        <source>the interpolated N is shorter than 1: normalise it before N.L and R</source>
        <translation>the interpolated N is shorter than 1: normalise it before N.L and R</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="593"/>
        <source>check where the lighting is evaluated: per pixel, per vertex or per triangle</source>
        <translation>check where the lighting is evaluated: per pixel, per vertex or per triangle</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="596"/>
        <source>check the sign of x in the projection or the screen mapping</source>
        <translation>check the sign of x in the projection or the screen mapping</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="597"/>
        <source>screen row 0 is the top: y = (1 - y_ndc) * height / 2</source>
        <translation>screen row 0 is the top: y = (1 - y_ndc) * height / 2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="598"/>
        <source>check the screen mapping&apos;s offsets and the first pixel of each span</source>
        <translation>check the screen mapping&apos;s offsets and the first pixel of each span</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="600"/>
        <source>where a pixel is sampled decides which pixels an edge covers (--rules)</source>
        <translation>where a pixel is sampled decides which pixels an edge covers (--rules)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="602"/>
        <source>check how screen coordinates become whole pixels ((int) truncates)</source>
        <translation>check how screen coordinates become whole pixels ((int) truncates)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="604"/>
        <source>the pixels exactly on an edge: which triangle (or both) covers them</source>
        <translation>the pixels exactly on an edge: which triangle (or both) covers them</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="606"/>
        <source>check how the colour becomes a byte: (int) truncates, + 0.5 rounds</source>
        <translation>check how the colour becomes a byte: (int) truncates, + 0.5 rounds</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="608"/>
        <source>clamp each channel to 255 before writing it as a byte</source>
        <translation>clamp each channel to 255 before writing it as a byte</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="609"/>
        <source>keep a depth buffer and write a pixel only when the fragment is nearer</source>
        <translation>keep a depth buffer and write a pixel only when the fragment is nearer</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="611"/>
        <source>the comparison of the depth test: &lt; keeps the first of two equal depths</source>
        <translation>the comparison of the depth test: &lt; keeps the first of two equal depths</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="613"/>
        <source>the colour (and alpha) of the pixels no triangle covers</source>
        <translation>the colour (and alpha) of the pixels no triangle covers</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="614"/>
        <source>the alpha written with each shaded pixel</source>
        <translation>the alpha written with each shaded pixel</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="615"/>
        <source>theirs - ours is %1 in %2 of the %3 covered channels that differ</source>
        <translation>theirs - ours is %1 in %2 of the %3 covered channels that differ</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="616"/>
        <source>theirs is within 2 of %1 times ours in %2 of the %3 covered channels that differ</source>
        <translation>theirs is within 2 of %1 times ours in %2 of the %3 covered channels that differ</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="618"/>
        <source>the scene rendered again with the fitted lighting gives their pixels</source>
        <translation>the scene rendered again with the fitted lighting gives their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="619"/>
        <source>compare the light&apos;s position, the intensities and the coefficients your program uses with the fitted ones</source>
        <translation>compare the light&apos;s position, the intensities and the coefficients your program uses with the fitted ones</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="620"/>
        <source>their lighting, fitted to their colours: %1</source>
        <translation>their lighting, fitted to their colours: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="621"/>
        <source>the lighting is fitted for a course camera and one positional light of the course&apos;s model</source>
        <translation>the lighting is fitted for a course camera and one positional light of the course&apos;s model</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="622"/>
        <source>the lighting is fitted for Phong-shaded draws of one material</source>
        <translation>the lighting is fitted for Phong-shaded draws of one material</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="623"/>
        <source>too few unclamped pixels inside triangles to fit the lighting</source>
        <translation>too few unclamped pixels inside triangles to fit the lighting</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="624"/>
        <source>the fitted light is at the light&apos;s world position: it was not taken to view coordinates</source>
        <translation>the fitted light is at the light&apos;s world position: it was not taken to view coordinates</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="625"/>
        <source>the fitted light is at [I] Pl: C was not subtracted</source>
        <translation>the fitted light is at [I] Pl: C was not subtracted</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="626"/>
        <source>the fitted light is ours with %1 negated</source>
        <translation>the fitted light is ours with %1 negated</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="627"/>
        <source>the fitted light is ours with %1 and %2 swapped</source>
        <translation>the fitted light is ours with %1 and %2 swapped</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="628"/>
        <source>the fitted n is half of ours: n halved</source>
        <translation>the fitted n is half of ours: n halved</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="629"/>
        <source>the command file read again with that command so gives their pixels</source>
        <translation>the command file read again with that command so gives their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="630"/>
        <source>every &apos;%1&apos; ignored (%2 of them, from line %3): the command never implemented</source>
        <translation>every &apos;%1&apos; ignored (%2 of them, from line %3): the command never implemented</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="632"/>
        <source>every &apos;%1&apos; multiplied on the other side (M = A M instead of M A), from line %2</source>
        <translation>every &apos;%1&apos; multiplied on the other side (M = A M instead of M A), from line %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="634"/>
        <source>every &apos;%1&apos; read column by column (the matrix transposed), from line %2</source>
        <translation>every &apos;%1&apos; read column by column (the matrix transposed), from line %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="636"/>
        <source>every &apos;%1&apos; with its angle taken as radians, from line %2</source>
        <translation>every &apos;%1&apos; with its angle taken as radians, from line %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="637"/>
        <source>every &apos;%1&apos; with s = f x up not normalised, from line %2</source>
        <translation>every &apos;%1&apos; with s = f x up not normalised, from line %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="638"/>
        <source>line %1: &apos;%2&apos; ignored</source>
        <translation>line %1: &apos;%2&apos; ignored</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="639"/>
        <source>line %1: &apos;%2&apos; multiplied on the other side (M = A M instead of M A)</source>
        <translation>line %1: &apos;%2&apos; multiplied on the other side (M = A M instead of M A)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="640"/>
        <source>line %1: &apos;%2&apos; read column by column (the matrix transposed)</source>
        <translation>line %1: &apos;%2&apos; read column by column (the matrix transposed)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="641"/>
        <source>line %1: &apos;%2&apos; with its angle taken as radians</source>
        <translation>line %1: &apos;%2&apos; with its angle taken as radians</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="642"/>
        <source>line %1: &apos;%2&apos; with s = f x up not normalised (the image stretched across)</source>
        <translation>line %1: &apos;%2&apos; with s = f x up not normalised (the image stretched across)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="643"/>
        <source>check that your program reads &apos;%1&apos; and applies it</source>
        <translation>check that your program reads &apos;%1&apos; and applies it</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="644"/>
        <source>seed 001: a transform multiplies the model/view on the right, M = M A</source>
        <translation>seed 001: a transform multiplies the model/view on the right, M = M A</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="645"/>
        <source>seed 001 writes a matrix row by row: the first four numbers are its first row</source>
        <translation>seed 001 writes a matrix row by row: the first four numbers are its first row</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="646"/>
        <source>seed 001&apos;s angles are in degrees: convert them before sin and cos</source>
        <translation>seed 001&apos;s angles are in degrees: convert them before sin and cos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="647"/>
        <source>lookat: normalise s = f x up before it goes into the matrix</source>
        <translation>lookat: normalise s = f x up before it goes into the matrix</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="648"/>
        <source>the camera&apos;s N not normalised before V - (V.N)N, nor after</source>
        <translation>the camera&apos;s N not normalised before V - (V.N)N, nor after</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="649"/>
        <source>the camera&apos;s U = V x N instead of N x V (x runs the other way)</source>
        <translation>the camera&apos;s U = V x N instead of N x V (x runs the other way)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="650"/>
        <source>the scene rendered again in view coordinates made with that basis gives their pixels</source>
        <translation>the scene rendered again in view coordinates made with that basis gives their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="651"/>
        <source>seed 000&apos;s Gram-Schmidt: normalise N first, then V - (V.N)N is V&apos;s part across N</source>
        <translation>seed 000&apos;s Gram-Schmidt: normalise N first, then V - (V.N)N is V&apos;s part across N</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="652"/>
        <source>seed 000: U = N x V, so that U, V, N is right-handed</source>
        <translation>seed 000: U = N x V, so that U, V, N is right-handed</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="653"/>
        <source>the vertex normals left at the length of their sums (not normalised)</source>
        <translation>the vertex normals left at the length of their sums (not normalised)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="654"/>
        <source>the triangle normals summed at their length (area-weighted) instead of normalised first</source>
        <translation>the triangle normals summed at their length (area-weighted) instead of normalised first</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="655"/>
        <source>seed 000: each vertex normal is the normalised sum of its triangles&apos; normals</source>
        <translation>seed 000: each vertex normal is the normalised sum of its triangles&apos; normals</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="656"/>
        <source>normalise each triangle&apos;s normal before adding it to its vertices</source>
        <translation>normalise each triangle&apos;s normal before adding it to its vertices</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="657"/>
        <source>the light not taken to view coordinates: its world position used as Pl_view</source>
        <translation>the light not taken to view coordinates: its world position used as Pl_view</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="658"/>
        <source>the light taken to view coordinates without subtracting C: [I] Pl instead of [I](Pl - C)</source>
        <translation>the light taken to view coordinates without subtracting C: [I] Pl instead of [I](Pl - C)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="659"/>
        <source>V = P&apos; instead of -P&apos; (L = P&apos; - Pl gives the same image)</source>
        <translation>V = P&apos; instead of -P&apos; (L = P&apos; - Pl gives the same image)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="660"/>
        <source>the ambient term Ia instead of Ia*ka</source>
        <translation>the ambient term Ia instead of Ia*ka</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="661"/>
        <source>each Phong term truncated to a whole byte before the sum</source>
        <translation>each Phong term truncated to a whole byte before the sum</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="662"/>
        <source>V.N, N.L and R.V tested against %1 instead of 0</source>
        <translation>V.N, N.L and R.V tested against %1 instead of 0</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="663"/>
        <source>the depth test reversed: the farther fragment wins (&gt; against a buffer cleared to -infinity, or to 0)</source>
        <translation>the depth test reversed: the farther fragment wins (&gt; against a buffer cleared to -infinity, or to 0)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="664"/>
        <source>every covered pixel&apos;s colour off by %1 (a constant offset)</source>
        <translation>every covered pixel&apos;s colour off by %1 (a constant offset)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="665"/>
        <source>every colour multiplied by %1 (a constant scale)</source>
        <translation>every colour multiplied by %1 (a constant scale)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="666"/>
        <source>every colour multiplied by 255: a colour scaled by 255 where it was already 0..255</source>
        <translation>every colour multiplied by 255: a colour scaled by 255 where it was already 0..255</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="668"/>
        <source>every colour divided by 255: a colour scaled to 0..1 where the scene&apos;s are 0..255</source>
        <translation>every colour divided by 255: a colour scaled to 0..1 where the scene&apos;s are 0..255</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="670"/>
        <source>the scene rendered again with the light where that transform puts it gives their pixels</source>
        <translation>the scene rendered again with the light where that transform puts it gives their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="671"/>
        <source>the scene rendered again with the farther fragment winning gives their pixels</source>
        <translation>the scene rendered again with the farther fragment winning gives their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="672"/>
        <source>our bytes moved by that constant give their pixels</source>
        <translation>our bytes moved by that constant give their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="673"/>
        <source>our colours multiplied by that constant give their pixels</source>
        <translation>our colours multiplied by that constant give their pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="674"/>
        <source>seed 000: the light goes to view coordinates as the vertices do, Pl_view = [I](Pl - C)</source>
        <translation>seed 000: the light goes to view coordinates as the vertices do, Pl_view = [I](Pl - C)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="675"/>
        <source>seed 000: Pl_view = [I](Pl - C): subtract C before the change of basis</source>
        <translation>seed 000: Pl_view = [I](Pl - C): subtract C before the change of basis</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="676"/>
        <source>V points from the surface to the camera: V = -P&apos; in view coordinates, and L = Pl - P&apos;</source>
        <translation>V points from the surface to the camera: V = -P&apos; in view coordinates, and L = Pl - P&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="677"/>
        <source>seed 000&apos;s ambient term is Ia*ka</source>
        <translation>seed 000&apos;s ambient term is Ia*ka</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="678"/>
        <source>add the terms as real numbers and make a byte once, at the end</source>
        <translation>add the terms as real numbers and make a byte once, at the end</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="679"/>
        <source>seed 000&apos;s special cases test against 0: V.N &lt; 0, N.L &lt; 0, R.V &lt; 0</source>
        <translation>seed 000&apos;s special cases test against 0: V.N &lt; 0, N.L &lt; 0, R.V &lt; 0</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="680"/>
        <source>the z-buffer starts at +infinity and a fragment is written when its z is smaller</source>
        <translation>the z-buffer starts at +infinity and a fragment is written when its z is smaller</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="681"/>
        <source>look for a constant added to every colour, or bytes made with an offset</source>
        <translation>look for a constant added to every colour, or bytes made with an offset</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="682"/>
        <source>look for a factor on every colour: an intensity scaled, or another colour scale</source>
        <translation>look for a factor on every colour: an intensity scaled, or another colour scale</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="683"/>
        <source>%1; no pixel that matches now would change</source>
        <translation>%1; no pixel that matches now would change</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="684"/>
        <source>%2; %1 pixel that matches now would differ</source>
        <translation>%2; %1 pixel that matches now would differ</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="685"/>
        <source>%2; %1 pixels that match now would differ</source>
        <translation>%2; %1 pixels that match now would differ</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="687"/>
        <source>cannot read the texture %1: %2</source>
        <translation>cannot read the texture %1: %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="689"/>
        <source>V is %1 degrees from the line of N: Gram-Schmidt keeps only that much of V, and the basis is orthonormal only to %2, less than a float&apos;s precision; choose a V farther from N</source>
        <translation>V is %1 degrees from the line of N: Gram-Schmidt keeps only that much of V, and the basis is orthonormal only to %2, less than a float&apos;s precision; choose a V farther from N</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="694"/>
        <source>cannot open: %1</source>
        <translation>cannot open: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="695"/>
        <source>the file has %1 MiB, more than the %2 MiB an input file may have</source>
        <translation>the file has %1 MiB, more than the %2 MiB an input file may have</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="697"/>
        <source>the file has more than the %1 MiB an input file may have</source>
        <translation>the file has more than the %1 MiB an input file may have</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="699"/>
        <source>not enough memory to read this file</source>
        <translation>not enough memory to read this file</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="700"/>
        <source>the built-in scene&apos;s files cannot be written: save it to a file of your own (Save As)</source>
        <translation>the built-in scene&apos;s files cannot be written: save it to a file of your own (Save As)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="703"/>
        <source>the object is not edited, so not saved</source>
        <translation>the object is not edited, so not saved</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="704"/>
        <source>cannot write into the built-in resources</source>
        <translation>cannot write into the built-in resources</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="705"/>
        <source>the camera was not saved, as it would not load again: %1</source>
        <translation>the camera was not saved, as it would not load again: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="706"/>
        <source>not saved: the text written does not read back as the same values</source>
        <translation>not saved: the text written does not read back as the same values</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="708"/>
        <source>cannot write the file: %1</source>
        <translation>cannot write the file: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="709"/>
        <source>only %1 of %2 bytes could be written (is the disk full?)</source>
        <translation>only %1 of %2 bytes could be written (is the disk full?)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="710"/>
        <source>cannot write the file (it is left as it was): %1</source>
        <translation>cannot write the file (it is left as it was): %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="712"/>
        <source>[rows, fragments], two whole numbers</source>
        <translation>[rows, fragments], two whole numbers</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="713"/>
        <source>[width, height], whole numbers from %1 to %2</source>
        <translation>[width, height], whole numbers from %1 to %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="714"/>
        <source>a list</source>
        <translation>a list</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="715"/>
        <source>a list of %1 numbers</source>
        <translation>a list of %1 numbers</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="716"/>
        <source>a list of 1 to 8 lights</source>
        <translation>a list of 1 to 8 lights</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="717"/>
        <source>a list of dock names</source>
        <translation>a list of dock names</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="718"/>
        <source>a number</source>
        <translation>a number</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="719"/>
        <source>a positive number or &quot;auto&quot;</source>
        <translation>a positive number or &quot;auto&quot;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="720"/>
        <source>a positive number or &quot;fit&quot;</source>
        <translation>a positive number or &quot;fit&quot;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="721"/>
        <source>a whole number from %1</source>
        <translation>a whole number from %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="722"/>
        <source>an object</source>
        <translation>an object</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="723"/>
        <source>expected %1 for &quot;%2&quot;, found %3</source>
        <translation>expected %1 for &quot;%2&quot;, found %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="724"/>
        <source>expected a lesson file: a JSON object with &quot;rasterlab_lesson&quot;: %1</source>
        <translation>expected a lesson file: a JSON object with &quot;rasterlab_lesson&quot;: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="726"/>
        <source>not a lesson file: %1</source>
        <translation>not a lesson file: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="727"/>
        <source>nothing</source>
        <translation>nothing</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="728"/>
        <source>null</source>
        <translation>null</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="729"/>
        <source>one of %1</source>
        <translation>one of %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="730"/>
        <source>text in quotes</source>
        <translation>text in quotes</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="731"/>
        <source>the text &apos;%1&apos;</source>
        <translation>the text &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="732"/>
        <source>true or false</source>
        <translation>true or false</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="733"/>
        <source>unknown key &quot;%1&quot; ignored (known here: %2)</source>
        <translation>unknown key &quot;%1&quot; ignored (known here: %2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="768"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="774"/>
        <source>%1: warning: %2</source>
        <translation>%1: warning: %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="775"/>
        <source>%1: note: %2</source>
        <translation>%1: note: %2</translation>
    </message>
</context>
<context>
    <name>StabilityPlot</name>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="156"/>
        <source>every point: error against time</source>
        <translation>every point: error against time</translation>
    </message>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="157"/>
        <source>time per frame (ms, log scale)</source>
        <translation>time per frame (ms, log scale)</translation>
    </message>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="172"/>
        <source>float</source>
        <translation>float</translation>
    </message>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="173"/>
        <source>double</source>
        <translation>double</translation>
    </message>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="190"/>
        <source>float against double, largest difference</source>
        <translation>float against double, largest difference</translation>
    </message>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="194"/>
        <source>y: colour error in byte steps (log; RMSE against the exact reference, or the largest float-double difference); x: stiffer to the right; a cross: the scene could not be rendered</source>
        <translation>y: colour error in byte steps (log; RMSE against the exact reference, or the largest float-double difference); x: stiffer to the right; a cross: the scene could not be rendered</translation>
    </message>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="268"/>
        <source>%1 (%2, log scale)</source>
        <translation>%1 (%2, log scale)</translation>
    </message>
</context>
<context>
    <name>rasterlab::AccuracyPanel</name>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="85"/>
        <source>The scene, camera and lights moved %1 to %2 units from the origin</source>
        <translation>The scene, camera and lights moved %1 to %2 units from the origin</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="90"/>
        <source>Everything scaled by %1 to %2 about the origin</source>
        <translation>Everything scaled by %1 to %2 about the origin</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="94"/>
        <source>Everything scaled by %1 to %2 about the eye: the object nearer</source>
        <translation>Everything scaled by %1 to %2 about the eye: the object nearer</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="97"/>
        <source>Each triangle cut around a sliver of %1 to %2 degrees</source>
        <translation>Each triangle cut around a sliver of %1 to %2 degrees</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="100"/>
        <source>Every material&apos;s shininess n set to %1 to %2</source>
        <translation>Every material&apos;s shininess n set to %1 to %2</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="103"/>
        <source>The camera&apos;s V %1 to %2 degrees from N</source>
        <translation>The camera&apos;s V %1 to %2 degrees from N</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="106"/>
        <source>The first light %1 to %2 times the scene&apos;s size above its surface</source>
        <translation>The first light %1 to %2 times the scene&apos;s size above its surface</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="152"/>
        <source>float and double differ by up to %1 byte steps (at %2); largest RMSE, float / double: %3.</source>
        <translation>float and double differ by up to %1 byte steps (at %2); largest RMSE, float / double: %3.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="159"/>
        <source>%1 of %2 points not rendered (the first at %3): %4</source>
        <translation>%1 of %2 points not rendered (the first at %3): %4</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="177"/>
        <source>&amp;Measure</source>
        <translation>&amp;Measure</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="180"/>
        <source>Render the scene in every mode and compare each with an exact ray-cast reference</source>
        <translation>Render the scene in every mode and compare each with an exact ray-cast reference</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="182"/>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="187"/>
        <source>1 sample a pixel</source>
        <translation>1 sample a pixel</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="188"/>
        <source>also 2x2 samples</source>
        <translation>also 2x2 samples</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="189"/>
        <source>also 4x4 samples</source>
        <translation>also 4x4 samples</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="196"/>
        <source>&amp;Stability sweep</source>
        <translation>&amp;Stability sweep</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="199"/>
        <source>Make the scene stiffer step by step and measure float and double under the course and gpu rules against the exact reference at each step</source>
        <translation>Make the scene stiffer step by step and measure float and double under the course and gpu rules against the exact reference at each step</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="203"/>
        <source>every axis</source>
        <translation>every axis</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="208"/>
        <source>The axes of stiffness to sweep</source>
        <translation>The axes of stiffness to sweep</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="214"/>
        <source>%v of %m points</source>
        <translation>%v of %m points</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="218"/>
        <source>Measures the error of each mode against an exact reference.</source>
        <translation>Measures the error of each mode against an exact reference.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="225"/>
        <source>Modes</source>
        <translation>Modes</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="226"/>
        <source>Stability</source>
        <translation>Stability</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="245"/>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="245"/>
        <source>Rules</source>
        <translation>Rules</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="245"/>
        <source>Precision</source>
        <translation>Precision</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="245"/>
        <source>Samples</source>
        <translation>Samples</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="246"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="246"/>
        <source>RMSE</source>
        <translation>RMSE</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="246"/>
        <source>Max error</source>
        <translation>Max error</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="246"/>
        <source>Within 1/255</source>
        <translation>Within 1/255</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="247"/>
        <source>Errors in byte steps (1/255) over the pixels both images cover</source>
        <translation>Errors in byte steps (1/255) over the pixels both images cover</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="271"/>
        <source>Click a pixel to compare the mode with the reference there</source>
        <translation>Click a pixel to compare the mode with the reference there</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="300"/>
        <source>The sweep makes the scene stiffer along each axis: where a curve leaves the floor, the arithmetic loses accuracy.</source>
        <translation>The sweep makes the scene stiffer along each axis: where a curve leaves the floor, the arithmetic loses accuracy.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="334"/>
        <source>The scene changed: measure again.</source>
        <translation>The scene changed: measure again.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/window/accuracy_panel.cpp" line="356"/>
        <source>Measuring %n mode(s) against the exact reference...</source>
        <translation>
            <numerusform>Measuring %n mode against the exact reference...</numerusform>
            <numerusform>Measuring %n modes against the exact reference...</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="379"/>
        <source>Cancelled.</source>
        <translation>Cancelled.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="380"/>
        <source>The measurement failed: %1</source>
        <translation>The measurement failed: %1</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="386"/>
        <source>%1 at %2x%3: %4 modes; the exact reference cast %5 rays in %6 ms.</source>
        <translation>%1 at %2x%3: %4 modes; the exact reference cast %5 rays in %6 ms.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="413"/>
        <source>Error against run time: %1, %2x%3</source>
        <translation>Error against run time: %1, %2x%3</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="457"/>
        <source>Sweeping %1 along %2...</source>
        <translation>Sweeping %1 along %2...</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="482"/>
        <source>Sweep cancelled.</source>
        <translation>Sweep cancelled.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="483"/>
        <source>The sweep failed: %1</source>
        <translation>The sweep failed: %1</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="490"/>
        <source>Error against stiffness: %1, %2x%3, %4 triangles</source>
        <translation>Error against stiffness: %1, %2x%3, %4 triangles</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="496"/>
        <source>%1 at %2x%3: %4 points in %5 s.</source>
        <translation>%1 at %2x%3: %4 points in %5 s.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="552"/>
        <source>%1 (%2): coverage differs on %3 pixels (%4); the largest error, %5 byte steps, is at (%6, %7). Click the map to compare a pixel.</source>
        <translation>%1 (%2): coverage differs on %3 pixels (%4); the largest error, %5 byte steps, is at (%6, %7). Click the map to compare a pixel.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="571"/>
        <source>Pixel (%1, %2), %3: mode %4, reference %5, difference %6 (byte steps).</source>
        <translation>Pixel (%1, %2), %3: mode %4, reference %5, difference %6 (byte steps).</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="577"/>
        <source>Coverage differs: %1 of %2 samples covered by the mode, %3 by the reference.</source>
        <translation>Coverage differs: %1 of %2 samples covered by the mode, %3 by the reference.</translation>
    </message>
</context>
<context>
    <name>rasterlab::AnimationPanel</name>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="30"/>
        <source>Animate: each draw moved by M(t)</source>
        <translation>Animate: each draw moved by M(t)</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="35"/>
        <location filename="../app/window/animation_panel.cpp" line="210"/>
        <source>Play</source>
        <translation>Play</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="40"/>
        <source>Play or pause the animation; paused, every stage view inspects the frame shown</source>
        <translation>Play or pause the animation; paused, every stage view inspects the frame shown</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="61"/>
        <source>Frames:</source>
        <translation>Frames:</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="64"/>
        <source>Frames a second:</source>
        <translation>Frames a second:</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="67"/>
        <source> °/s</source>
        <translation> °/s</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="68"/>
        <source>Turn:</source>
        <translation>Turn:</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="69"/>
        <source>Turn about the camera&apos;s up (a turntable)</source>
        <translation>Turn about the camera&apos;s up (a turntable)</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="97"/>
        <source>Axis:</source>
        <translation>Axis:</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="99"/>
        <source>Moves (units/s):</source>
        <translation>Moves (units/s):</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="100"/>
        <source>Scale:</source>
        <translation>Scale:</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="111"/>
        <source>&lt;i&gt;The animation belongs to this session: course files have no such field, and saving the camera or lighting does not write it.&lt;/i&gt;</source>
        <translation>&lt;i&gt;The animation belongs to this session: course files have no such field, and saving the camera or lighting does not write it.&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="210"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="222"/>
        <source>Frame %1 of %2, t = %3 / %4 = %5 s</source>
        <translation>Frame %1 of %2, t = %3 / %4 = %5 s</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="241"/>
        <source>&lt;p&gt;M(t) = T(v t) · T(c) · R(axis, ω t) · S · T(−c): not applied (the animation is off, so M is the identity).&lt;/p&gt;</source>
        <translation>&lt;p&gt;M(t) = T(v t) · T(c) · R(axis, ω t) · S · T(−c): not applied (the animation is off, so M is the identity).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="257"/>
        <source>&lt;p&gt;M(t) = T(v t) · T(c) · R(axis, ω t) · S · T(−c), at t = %1 s:&lt;br&gt;c = %2 (the centre of the bounding box), axis = %3,&lt;br&gt;ω t = %4 °/s · %1 s = %5°, v t = %6, S = diag%7&lt;/p&gt;</source>
        <translation>&lt;p&gt;M(t) = T(v t) · T(c) · R(axis, ω t) · S · T(−c), at t = %1 s:&lt;br&gt;c = %2 (the centre of the bounding box), axis = %3,&lt;br&gt;ω t = %4 °/s · %1 s = %5°, v t = %6, S = diag%7&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="265"/>
        <source>&lt;p&gt;Normals are moved by the inverse transpose of M (stage 3).&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normals are moved by the inverse transpose of M (stage 3).&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>rasterlab::BreakpointsView</name>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="37"/>
        <source>triangle %1 starts</source>
        <translation>triangle %1 starts</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="39"/>
        <source>a triangle reaches scanline %1</source>
        <translation>a triangle reaches scanline %1</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="41"/>
        <source>first depth rejection at (%1, %2)</source>
        <translation>first depth rejection at (%1, %2)</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="43"/>
        <source>N.L &lt; 0 at (%1, %2)</source>
        <translation>N.L &lt; 0 at (%1, %2)</translation>
    </message>
    <message numerus="yes">
        <location filename="../views/breakpoints_view.cpp" line="45"/>
        <source>any pixel written %n time(s)</source>
        <translation>
            <numerusform>any pixel written %n time</numerusform>
            <numerusform>any pixel written %n times</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../views/breakpoints_view.cpp" line="46"/>
        <source>(%1, %2) written %n time(s)</source>
        <translation>
            <numerusform>(%1, %2) written %n time</numerusform>
            <numerusform>(%1, %2) written %n times</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="60"/>
        <source>At triangle</source>
        <translation>At triangle</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="61"/>
        <source>At scanline</source>
        <translation>At scanline</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="62"/>
        <source>First depth rejection at the picked pixel</source>
        <translation>First depth rejection at the picked pixel</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="64"/>
        <source>N.L &lt; 0 at the picked pixel</source>
        <translation>N.L &lt; 0 at the picked pixel</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="65"/>
        <source>A pixel written n times</source>
        <translation>A pixel written n times</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="66"/>
        <source>Stop when</source>
        <translation>Stop when</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="70"/>
        <source>Number</source>
        <translation>Number</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="72"/>
        <source>the picked pixel</source>
        <translation>the picked pixel</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="73"/>
        <source>any pixel</source>
        <translation>any pixel</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="74"/>
        <source>Pixel</source>
        <translation>Pixel</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="77"/>
        <source>&amp;Add</source>
        <translation>&amp;Add</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="79"/>
        <source>&amp;Remove</source>
        <translation>&amp;Remove</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="80"/>
        <source>Remove A&amp;ll</source>
        <translation>Remove A&amp;ll</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="90"/>
        <source>Breakpoint</source>
        <translation>Breakpoint</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="98"/>
        <source>Pick a pixel in the image first.</source>
        <translation>Pick a pixel in the image first.</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="115"/>
        <source>Stopped: %1</source>
        <translation>Stopped: %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::CameraBasisCanvas</name>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="155"/>
        <source>Drag to turn the scene, wheel to zoom, double-click to reset.</source>
        <translation>Drag to turn the scene, wheel to zoom, double-click to reset.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="158"/>
        <source>Reset view</source>
        <translation>Reset view</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="159"/>
        <source>Turn the 3D drawing back to where it started</source>
        <translation>Turn the 3D drawing back to where it started</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="422"/>
        <source>window (d = %1)</source>
        <translation>window (d = %1)</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="426"/>
        <source>frustum</source>
        <translation>frustum</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="441"/>
        <source>N given, |N| = %1</source>
        <translation>N given, |N| = %1</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="444"/>
        <source>V given, |V| = %1</source>
        <translation>V given, |V| = %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::CameraBasisView</name>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="512"/>
        <source>Previous step</source>
        <translation>Previous step</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="516"/>
        <source>Next step</source>
        <translation>Next step</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="634"/>
        <source>The camera was rejected: %1</source>
        <translation>The camera was rejected: %1</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="637"/>
        <source>No frame yet.</source>
        <translation>No frame yet.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="639"/>
        <source>This stage is skipped: %1.</source>
        <translation>This stage is skipped: %1.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="641"/>
        <source>the frame has no camera basis</source>
        <translation>the frame has no camera basis</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="648"/>
        <source>&lt;p&gt;&lt;b&gt;Camera basis.&lt;/b&gt; From the course camera (C, N, V) Gram-Schmidt makes the orthonormal basis U, V, N of view space. A scene whose draws carry their own model/view matrices (HW2 command files) has no course camera: this stage does nothing for it.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Camera basis.&lt;/b&gt; From the course camera (C, N, V) Gram-Schmidt makes the orthonormal basis U, V, N of view space. A scene whose draws carry their own model/view matrices (HW2 command files) has no course camera: this stage does nothing for it.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="661"/>
        <source>N and V are nearly parallel: |V − (V·N) N| / |V| = %1, below %2. The basis is ill-conditioned: a tiny change of N or V turns U and V a lot. Choose a V further from N.</source>
        <translation>N and V are nearly parallel: |V − (V·N) N| / |V| = %1, below %2. The basis is ill-conditioned: a tiny change of N or V turns U and V a lot. Choose a V further from N.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="676"/>
        <source>1. N := N / |N| = %1 / %2 = %3</source>
        <translation>1. N := N / |N| = %1 / %2 = %3</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="678"/>
        <source>2. V := V − (V·N) N: V·N = %1, (V·N) N = %2, V − (V·N) N = %3</source>
        <translation>2. V := V − (V·N) N: V·N = %1, (V·N) N = %2, V − (V·N) N = %3</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="680"/>
        <source>3. V := V / |V| = %1 / %2 = %3</source>
        <translation>3. V := V / |V| = %1 / %2 = %3</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="682"/>
        <source>4. U := N × V = %1 × %2 = %3</source>
        <translation>4. U := N × V = %1 × %2 = %3</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="684"/>
        <source>U·V = %1, U·N = %2, V·N = %3, |U| − 1 = %4, |V| − 1 = %5, |N| − 1 = %6; largest %7</source>
        <translation>U·V = %1, U·N = %2, V·N = %3, |U| − 1 = %4, |V| − 1 = %5, |N| − 1 = %6; largest %7</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="691"/>
        <source>N and V %1 degrees apart (under %2 degrees from the line of N, the residuals pass a float&apos;s precision)</source>
        <translation>N and V %1 degrees apart (under %2 degrees from the line of N, the residuals pass a float&apos;s precision)</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="713"/>
        <source>&lt;b&gt;viewFromWorld&lt;/b&gt; = [U; V; N] · translate(−C): rows U, V, N, then (0 0 0 1); the last column is −U·C, −V·C, −N·C.</source>
        <translation>&lt;b&gt;viewFromWorld&lt;/b&gt; = [U; V; N] · translate(−C): rows U, V, N, then (0 0 0 1); the last column is −U·C, −V·C, −N·C.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="725"/>
        <source>&lt;p&gt;Vertex 1: P = %1, P − C = %2, pView = (U·(P − C), V·(P − C), N·(P − C)) = %3%4.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Vertex 1: P = %1, P − C = %2, pView = (U·(P − C), V·(P − C), N·(P − C)) = %3%4.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="728"/>
        <source>, in front of the camera (z &gt; 0)</source>
        <translation>, in front of the camera (z &gt; 0)</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="729"/>
        <source>, behind the camera (z ≤ 0)</source>
        <translation>, behind the camera (z ≤ 0)</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="732"/>
        <source>&lt;p&gt;&lt;b&gt;Camera basis.&lt;/b&gt; Gram-Schmidt keeps the direction of N (where the camera looks), removes from V its part along N so that up is perpendicular to the view direction, and completes the frame with U = N × V, the image&apos;s right. viewFromWorld = [U; V; N] (P − C) puts the camera at the origin looking along +z.&lt;/p&gt;&lt;p&gt;C = %1, N = %2, V = %3, d = %4, hx = %5, hy = %6.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Camera basis.&lt;/b&gt; Gram-Schmidt keeps the direction of N (where the camera looks), removes from V its part along N so that up is perpendicular to the view direction, and completes the frame with U = N × V, the image&apos;s right. viewFromWorld = [U; V; N] (P − C) puts the camera at the origin looking along +z.&lt;/p&gt;&lt;p&gt;C = %1, N = %2, V = %3, d = %4, hx = %5, hy = %6.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="764"/>
        <source>Step %1 of 4</source>
        <translation>Step %1 of 4</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="779"/>
        <source>Step forward to normalise N.</source>
        <translation>Step forward to normalise N.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="780"/>
        <source>Step forward to remove from V its part along N.</source>
        <translation>Step forward to remove from V its part along N.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="781"/>
        <source>Step forward to normalise V.</source>
        <translation>Step forward to normalise V.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="782"/>
        <source>Step forward to make U = N × V.</source>
        <translation>Step forward to make U = N × V.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="783"/>
        <source>The basis is complete; the frustum is drawn with it.</source>
        <translation>The basis is complete; the frustum is drawn with it.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="796"/>
        <source>&lt;b&gt;Orthonormality residuals&lt;/b&gt; (0 up to rounding): %1</source>
        <translation>&lt;b&gt;Orthonormality residuals&lt;/b&gt; (0 up to rounding): %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::CheckPanel</name>
    <message>
        <location filename="../app/window/check_panel.cpp" line="53"/>
        <source>python3 stages.py</source>
        <translation>python3 stages.py</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="55"/>
        <source>The command that starts your program, run by /bin/sh in the folder below; it answers the stage protocol on its standard input and output (docs/stage-protocol.md).</source>
        <translation>The command that starts your program, run by /bin/sh in the folder below; it answers the stage protocol on its standard input and output (docs/stage-protocol.md).</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="58"/>
        <source>Command:</source>
        <translation>Command:</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="62"/>
        <source>Browse...</source>
        <translation>Browse...</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="65"/>
        <source>Folder:</source>
        <translation>Folder:</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="69"/>
        <source>Check</source>
        <translation>Check</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="71"/>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="73"/>
        <source>Stop at the First Departure</source>
        <translation>Stop at the First Departure</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="75"/>
        <source>Step the frame to where the selected stage first departs from the lecture&apos;s</source>
        <translation>Step the frame to where the selected stage first departs from the lecture&apos;s</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="81"/>
        <source>Chained</source>
        <translation>Chained</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="83"/>
        <source>Give each stage your program&apos;s own earlier answers as its input, to see how errors add up (unticked, each stage gets RasterLab&apos;s, so no mistake hides another)</source>
        <translation>Give each stage your program&apos;s own earlier answers as its input, to see how errors add up (unticked, each stage gets RasterLab&apos;s, so no mistake hides another)</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="95"/>
        <source>Compare Their Frame</source>
        <translation>Compare Their Frame</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="97"/>
        <source>Their whole frame in the Compare dock: each pixel&apos;s colour beside ours, and the Phong term that would have to change</source>
        <translation>Their whole frame in the Compare dock: each pixel&apos;s colour beside ours, and the Phong term that would have to change</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="114"/>
        <source>Stage</source>
        <translation>Stage</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="114"/>
        <source>Verdict</source>
        <translation>Verdict</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="114"/>
        <source>Elements</source>
        <translation>Elements</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="114"/>
        <source>Likely cause</source>
        <translation>Likely cause</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="151"/>
        <source>Your Program&apos;s Folder</source>
        <translation>Your Program&apos;s Folder</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="194"/>
        <source>A check is running.</source>
        <translation>A check is running.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="196"/>
        <source>Give the command that starts your program.</source>
        <translation>Give the command that starts your program.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="199"/>
        <source>The folder %1 does not exist.</source>
        <translation>The folder %1 does not exist.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="201"/>
        <source>There is no frame to check against.</source>
        <translation>There is no frame to check against.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="225"/>
        <source>Checking %1...</source>
        <translation>Checking %1...</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="243"/>
        <source>cancelled</source>
        <translation>cancelled</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="243"/>
        <source>done</source>
        <translation>done</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="253"/>
        <source>Over our image: each vertex that departs, ours a green dot, theirs a red cross, joined by a line.</source>
        <translation>Over our image: each vertex that departs, ours a green dot, theirs a red cross, joined by a line.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="257"/>
        <source>Over our image: magenta, pixels only we cover; cyan, pixels only they cover.</source>
        <translation>Over our image: magenta, pixels only we cover; cyan, pixels only they cover.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="261"/>
        <source>Over our image: red, pixels another triangle wins (or at another depth); magenta, only ours keeps one; cyan, only theirs.</source>
        <translation>Over our image: red, pixels another triangle wins (or at another depth); magenta, only ours keeps one; cyan, only theirs.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="265"/>
        <source>Over our image: red, pixels whose colour differs by more than 1.</source>
        <translation>Over our image: red, pixels whose colour differs by more than 1.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="274"/>
        <source>passed</source>
        <translation>passed</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="276"/>
        <source>failed</source>
        <translation>failed</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="278"/>
        <source>unsupported</source>
        <translation>unsupported</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="280"/>
        <source>broken</source>
        <translation>broken</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="323"/>
        <source>not applied: %1</source>
        <translation>not applied: %1</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="332"/>
        <source>Protected by: %1.</source>
        <translation>Protected by: %1.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="333"/>
        <source>Protected by: %1. Not applied: %2.</source>
        <translation>Protected by: %1. Not applied: %2.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="337"/>
        <source>Not checked: %1</source>
        <translation>Not checked: %1</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="343"/>
        <source>%1 of %2 differ</source>
        <translation>%1 of %2 differ</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="361"/>
        <source>Every stage passed (%1 s).</source>
        <translation>Every stage passed (%1 s).</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="410"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="414"/>
        <source>First departure: %1: theirs %2, ours %3</source>
        <translation>First departure: %1: theirs %2, ours %3</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="419"/>
        <source>Likely cause: %1 (explains %2 of %3, %4% of the difference)</source>
        <translation>Likely cause: %1 (explains %2 of %3, %4% of the difference)</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="425"/>
        <source>No known mistake of this stage gives their answer.</source>
        <translation>No known mistake of this stage gives their answer.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="427"/>
        <source>Unexplained: %1 of %2.</source>
        <translation>Unexplained: %1 of %2.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="428"/>
        <source>In numbers: %1</source>
        <translation>In numbers: %1</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="430"/>
        <source>Carried from the earlier stages: %1 elements of the lecture&apos;s answer change with what was sent.</source>
        <translation>Carried from the earlier stages: %1 elements of the lecture&apos;s answer change with what was sent.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="435"/>
        <source>Tolerance: %1</source>
        <translation>Tolerance: %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::CompareImage</name>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="102"/>
        <source>no such file</source>
        <translation>no such file</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="106"/>
        <source>the file is empty</source>
        <translation>the file is empty</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="130"/>
        <source>the PNG is cut short (it does not end with its IEND chunk)</source>
        <translation>the PNG is cut short (it does not end with its IEND chunk)</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="104"/>
        <source>a folder, not an image</source>
        <translation>a folder, not an image</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="29"/>
        <source>the TGA header is cut short</source>
        <translation>the TGA header is cut short</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="37"/>
        <source>a TGA image of a kind RasterLab does not read (only 8-bit grey and 24- or 32-bit colour, plain or run-length encoded)</source>
        <translation>a TGA image of a kind RasterLab does not read (only 8-bit grey and 24- or 32-bit colour, plain or run-length encoded)</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="49"/>
        <location filename="../app/compare/compare_image.cpp" line="75"/>
        <source>the TGA image is cut short</source>
        <translation>the TGA image is cut short</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="53"/>
        <source>the TGA image is %1x%2, larger than RasterLab reads</source>
        <translation>the TGA image is %1x%2, larger than RasterLab reads</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="125"/>
        <source>not an image RasterLab reads (PNG, PPM, BMP, TGA or JPEG)</source>
        <translation>not an image RasterLab reads (PNG, PPM, BMP, TGA or JPEG)</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="126"/>
        <source>not an image RasterLab reads (PNG, PPM, BMP, TGA or JPEG): a %1 image</source>
        <translation>not an image RasterLab reads (PNG, PPM, BMP, TGA or JPEG): a %1 image</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="144"/>
        <source>cannot read the %1 image: %2</source>
        <translation>cannot read the %1 image: %2</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="172"/>
        <source>a %1 image</source>
        <translation>a %1 image</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="174"/>
        <source>, lossy: compared with a tolerance of %1 per channel</source>
        <translation>, lossy: compared with a tolerance of %1 per channel</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="175"/>
        <source>, without alpha: colours compared, alpha taken as ours</source>
        <translation>, without alpha: colours compared, alpha taken as ours</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="205"/>
        <source>the image is %1, ours is %2</source>
        <translation>the image is %1, ours is %2</translation>
    </message>
</context>
<context>
    <name>rasterlab::ComparePanel</name>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="144"/>
        <location filename="../app/window/compare_panel.cpp" line="148"/>
        <source>R %1, G %2, B %3, A %4</source>
        <translation>R %1, G %2, B %3, A %4</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="25"/>
        <source>red</source>
        <translation>red</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="27"/>
        <source>green</source>
        <translation>green</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="29"/>
        <source>blue</source>
        <translation>blue</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="31"/>
        <source>alpha</source>
        <translation>alpha</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="38"/>
        <source>%1 and %2</source>
        <translation>%1 and %2</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="163"/>
        <source>Side by side</source>
        <translation>Side by side</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="164"/>
        <source>Flicker</source>
        <translation>Flicker</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="165"/>
        <source>Difference</source>
        <translation>Difference</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="167"/>
        <source>Theirs beside ours, one after the other twice a second, or the pixels that differ</source>
        <translation>Theirs beside ours, one after the other twice a second, or the pixels that differ</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="170"/>
        <source>Differ by more than</source>
        <translation>Differ by more than</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="176"/>
        <source>The difference view shows the pixels where some channel differs by more than this (0: every difference)</source>
        <translation>The difference view shows the pixels where some channel differs by more than this (0: every difference)</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="181"/>
        <source>Compare Again</source>
        <translation>Compare Again</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="184"/>
        <source>The scene changed since the comparison: compare their image with the scene shown now</source>
        <translation>The scene changed since the comparison: compare their image with the scene shown now</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="219"/>
        <source>File &gt; Compare with Image... compares a PNG of your own renderer with this scene&apos;s render.</source>
        <translation>File &gt; Compare with Image... compares a PNG of your own renderer with this scene&apos;s render.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="308"/>
        <source>There is no render to compare with yet.</source>
        <translation>There is no render to compare with yet.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="271"/>
        <source>Their image: %1.</source>
        <translation>Their image: %1.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="282"/>
        <source>Cropped to %1x%2 at (%3, %4) from %5x%6: the frame found inside it.</source>
        <translation>Cropped to %1x%2 at (%3, %4) from %5x%6: the frame found inside it.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="435"/>
        <location filename="../app/window/compare_panel.cpp" line="438"/>
        <source>Theirs</source>
        <translation>Theirs</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="435"/>
        <location filename="../app/window/compare_panel.cpp" line="438"/>
        <source>Ours</source>
        <translation>Ours</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/window/compare_panel.cpp" line="443"/>
        <source>%n pixel(s) differ by more than %1</source>
        <translation>
            <numerusform>%n pixel differs by more than %1</numerusform>
            <numerusform>%n pixels differ by more than %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="521"/>
        <source>%1 against our render (%2x%3): %4 pixels compared, %5 differ (%6%).</source>
        <translation>%1 against our render (%2x%3): %4 pixels compared, %5 differ (%6%).</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="530"/>
        <source>Their image is unlit: one colour %1 wherever it covers. Only coverage is compared (our covered pixels in that colour), and only projection and scan conversion mistakes are tried.</source>
        <translation>Their image is unlit: one colour %1 wherever it covers. Only coverage is compared (our covered pixels in that colour), and only projection and scan conversion mistakes are tried.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="539"/>
        <source>Largest difference per channel: %1.</source>
        <translation>Largest difference per channel: %1.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="540"/>
        <source>Mean difference per channel, over the differing pixels: %1.</source>
        <translation>Mean difference per channel, over the differing pixels: %1.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="542"/>
        <source>Pixels covered: %1 by both, %2 only by ours (our depth buffer), %3 only by theirs (not the background).</source>
        <translation>Pixels covered: %1 by both, %2 only by ours (our depth buffer), %3 only by theirs (not the background).</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="562"/>
        <source>Diagnosis, each mistake applied before the next is ranked:</source>
        <translation>Diagnosis, each mistake applied before the next is ranked:</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="568"/>
        <source>Removes %1% of the difference; makes %2 differing pixels match.</source>
        <translation>Removes %1% of the difference; makes %2 differing pixels match.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="549"/>
        <source>The scene has changed since this comparison: Compare Again compares their image with the scene shown now.</source>
        <translation>The scene has changed since this comparison: Compare Again compares their image with the scene shown now.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="188"/>
        <source>Render Ours with the Fitted Lighting</source>
        <translation>Render Ours with the Fitted Lighting</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="191"/>
        <source>Set the light&apos;s position, Ia, Il, kd, ks and n to the values fitted to their colours (one edit, undoable), and render ours with them</source>
        <translation>Set the light&apos;s position, Ia, Il, kd, ks and n to the values fitted to their colours (one edit, undoable), and render ours with them</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="331"/>
        <source>Comparing %1 with our render...</source>
        <translation>Comparing %1 with our render...</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="332"/>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="334"/>
        <source>Compare with Image</source>
        <translation>Compare with Image</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="362"/>
        <source>The comparison with %1 was cancelled.</source>
        <translation>The comparison with %1 was cancelled.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="477"/>
        <source>light x (view)</source>
        <translation>light x (view)</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="477"/>
        <source>light y (view)</source>
        <translation>light y (view)</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="478"/>
        <source>light z (view)</source>
        <translation>light z (view)</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="478"/>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="479"/>
        <source>ambient Ia*ka R</source>
        <translation>ambient Ia*ka R</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="479"/>
        <source>ambient Ia*ka G</source>
        <translation>ambient Ia*ka G</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="480"/>
        <source>ambient Ia*ka B</source>
        <translation>ambient Ia*ka B</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="480"/>
        <source>diffuse Il*Od*kd R</source>
        <translation>diffuse Il*Od*kd R</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="481"/>
        <source>diffuse Il*Od*kd G</source>
        <translation>diffuse Il*Od*kd G</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="481"/>
        <source>diffuse Il*Od*kd B</source>
        <translation>diffuse Il*Od*kd B</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="482"/>
        <source>specular Il*ks R</source>
        <translation>specular Il*ks R</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="482"/>
        <source>specular Il*ks G</source>
        <translation>specular Il*ks G</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="483"/>
        <source>specular Il*ks B</source>
        <translation>specular Il*ks B</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="535"/>
        <source>White wherever it covers is also what a lit image becomes with every colour multiplied by 255 (a colour scaled by 255 where it was already 0..255).</source>
        <translation>White wherever it covers is also what a lit image becomes with every colour multiplied by 255 (a colour scaled by 255 where it was already 0..255).</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="556"/>
        <source>The images are the same.</source>
        <translation>The images are the same.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="558"/>
        <source>Diagnosis: none of the mistakes RasterLab knows explains these differences.</source>
        <translation>Diagnosis: none of the mistakes RasterLab knows explains these differences.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="573"/>
        <source>Evidence: %1</source>
        <translation>Evidence: %1</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="574"/>
        <source>Check: %1</source>
        <translation>Check: %1</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="576"/>
        <source>At (%1, %2): ours %3, theirs %4</source>
        <translation>At (%1, %2): ours %3, theirs %4</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="586"/>
        <source>Unexplained: %1% of the difference; %2 pixels still differ with every mistake above applied.</source>
        <translation>Unexplained: %1% of the difference; %2 pixels still differ with every mistake above applied.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="594"/>
        <source>None of the known mistakes explains most of this difference.</source>
        <translation>None of the known mistakes explains most of this difference.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="599"/>
        <source>Lighting fitted to their colours</source>
        <translation>Lighting fitted to their colours</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="601"/>
        <source>%1 pixels inside triangles, their image carried back onto ours by the move above: rms %2 with ours, %3 fitted.</source>
        <translation>%1 pixels inside triangles, their image carried back onto ours by the move above: rms %2 with ours, %3 fitted.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="603"/>
        <source>%1 pixels inside triangles: rms %2 with ours, %3 fitted.</source>
        <translation>%1 pixels inside triangles: rms %2 with ours, %3 fitted.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="610"/>
        <source>%1: theirs %2 ± %3, ours %4</source>
        <translation>%1: theirs %2 ± %3, ours %4</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="628"/>
        <source>Pick a pixel (here or on the image) to see their colour beside ours.</source>
        <translation>Pick a pixel (here or on the image) to see their colour beside ours.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="641"/>
        <source>Their image is moved (the first finding): this pixel&apos;s point of the surface is outside it.</source>
        <translation>Their image is moved (the first finding): this pixel&apos;s point of the surface is outside it.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="645"/>
        <source>Their image is moved (the first finding): this pixel&apos;s point of the surface is their pixel (%1, %2).</source>
        <translation>Their image is moved (the first finding): this pixel&apos;s point of the surface is their pixel (%1, %2).</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="651"/>
        <source>Pixel (%1, %2): theirs %3, ours %4.</source>
        <translation>Pixel (%1, %2): theirs %3, ours %4.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="658"/>
        <source>minus %1 in %2</source>
        <translation>minus %1 in %2</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="659"/>
        <source>plus %1 in %2</source>
        <translation>plus %1 in %2</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="662"/>
        <source>Their colour is ours.</source>
        <translation>Their colour is ours.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="666"/>
        <source>Their colour is ours %1.</source>
        <translation>Their colour is ours %1.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="668"/>
        <source>The scene has changed since the comparison: the lighting shown now is not the one compared.</source>
        <translation>The scene has changed since the comparison: the lighting shown now is not the one compared.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="680"/>
        <source>No triangle of ours covers this pixel: it is the background.</source>
        <translation>No triangle of ours covers this pixel: it is the background.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="684"/>
        <source>The lighting of this pixel is not known.</source>
        <translation>The lighting of this pixel is not known.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="686"/>
        <source>The terms that would have to change are worked out for the course&apos;s lighting model in flat or Phong shading; this pixel is shaded otherwise (the pixel inspector shows how).</source>
        <translation>The terms that would have to change are worked out for the course&apos;s lighting model in flat or Phong shading; this pixel is shaded otherwise (the pixel inspector shows how).</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="62"/>
        <source>the ambient term Ia·ka</source>
        <translation>the ambient term Ia·ka</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="63"/>
        <source>the diffuse term Il·Od·kd·(N·L)</source>
        <translation>the diffuse term Il·Od·kd·(N·L)</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="64"/>
        <source>the specular term Il·ks·(R·V)^n</source>
        <translation>the specular term Il·ks·(R·V)^n</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="80"/>
        <source>• %1 is 0 in %2 here: changing it alone cannot give their colour.</source>
        <translation>• %1 is 0 in %2 here: changing it alone cannot give their colour.</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="85"/>
        <source>• %1 would have to be below 0 in %2: not this term alone.</source>
        <translation>• %1 would have to be below 0 in %2: not this term alone.</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="102"/>
        <source>• %1 would have to be %2 instead of %3, × %4 per channel</source>
        <translation>• %1 would have to be %2 instead of %3, × %4 per channel</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="105"/>
        <source>: the term left out</source>
        <translation>: the term left out</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="108"/>
        <source>: that is the term times Od %1</source>
        <translation>: that is the term times Od %1</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="111"/>
        <source>: that is the term without Od %1</source>
        <translation>: that is the term without Od %1</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="117"/>
        <source>(%1: 255 in both images, clamped; any value at least as high gives it.)</source>
        <translation>(%1: 255 in both images, clamped; any value at least as high gives it.)</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="120"/>
        <source>No term changed by a simple factor (left out, times Od, without Od) gives their colour: look at several terms, or at what the diagnosis says.</source>
        <translation>No term changed by a simple factor (left out, times Od, without Od) gives their colour: look at several terms, or at what the diagnosis says.</translation>
    </message>
</context>
<context>
    <name>rasterlab::EditPanel</name>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="218"/>
        <source>One kd for the three channels (the UFPE files have one number): changing one changes all three</source>
        <translation>One kd for the three channels (the UFPE files have one number): changing one changes all three</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="259"/>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="259"/>
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="259"/>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="262"/>
        <location filename="../app/window/edit_panel.cpp" line="725"/>
        <source>Camera</source>
        <translation>Camera</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="264"/>
        <source>C: the camera&apos;s position (world)</source>
        <translation>C: the camera&apos;s position (world)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="267"/>
        <source>N: the view direction (normalised by the camera basis)</source>
        <translation>N: the view direction (normalised by the camera basis)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="269"/>
        <source>V: the up vector (made orthogonal to N by Gram-Schmidt)</source>
        <translation>V: the up vector (made orthogonal to N by Gram-Schmidt)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="271"/>
        <source>d: the distance from C to the projection plane</source>
        <translation>d: the distance from C to the projection plane</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="273"/>
        <source>hx: half the width of the window on the projection plane</source>
        <translation>hx: half the width of the window on the projection plane</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="275"/>
        <source>hy: half the height of the window on the projection plane</source>
        <translation>hy: half the height of the window on the projection plane</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="279"/>
        <source>Light</source>
        <translation>Light</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="282"/>
        <source>The light whose values are shown</source>
        <translation>The light whose values are shown</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="288"/>
        <source>Add a light: a copy of the light shown</source>
        <translation>Add a light: a copy of the light shown</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="293"/>
        <source>Remove the light shown (the scene keeps one light at least)</source>
        <translation>Remove the light shown (the scene keeps one light at least)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="302"/>
        <source>Pl: the light&apos;s position (world), or the direction toward it for a directional light</source>
        <translation>Pl: the light&apos;s position (world), or the direction toward it for a directional light</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="305"/>
        <source>Directional (w = 0)</source>
        <translation>Directional (w = 0)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="306"/>
        <source>A directional light is infinitely far: L is the same everywhere and it is not attenuated</source>
        <translation>A directional light is infinitely far: L is the same everywhere and it is not attenuated</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="310"/>
        <source>Il: the light&apos;s colour, 0 to 255 per channel</source>
        <translation>Il: the light&apos;s colour, 0 to 255 per channel</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="314"/>
        <source>att</source>
        <translation>att</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="315"/>
        <source>Attenuation: the light&apos;s diffuse and specular terms are divided by kc + kl d + kq d², d its distance to the point (1 0 0: none)</source>
        <translation>Attenuation: the light&apos;s diffuse and specular terms are divided by kc + kl d + kq d², d its distance to the point (1 0 0: none)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="318"/>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="319"/>
        <source>A spot lights only the points within its cutoff angle of its direction</source>
        <translation>A spot lights only the points within its cutoff angle of its direction</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="322"/>
        <source>D: the direction the spot points to (world)</source>
        <translation>D: the direction the spot points to (world)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="323"/>
        <source>cut</source>
        <translation>cut</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="324"/>
        <source>The spot&apos;s cutoff angle, 0 to 90 degrees</source>
        <translation>The spot&apos;s cutoff angle, 0 to 90 degrees</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="325"/>
        <source>exp</source>
        <translation>exp</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="326"/>
        <source>The spot&apos;s exponent: its light falls off as (-L.D)^exp toward the edge</source>
        <translation>The spot&apos;s exponent: its light falls off as (-L.D)^exp toward the edge</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="330"/>
        <source>Ambient</source>
        <translation>Ambient</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="333"/>
        <source>Ia: the ambient light&apos;s colour, 0 to 255 per channel</source>
        <translation>Ia: the ambient light&apos;s colour, 0 to 255 per channel</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="335"/>
        <source>ka: the ambient coefficient, 0 to 1</source>
        <translation>ka: the ambient coefficient, 0 to 1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="338"/>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="341"/>
        <source>kd: the diffuse coefficient of each channel, 0 to 1</source>
        <translation>kd: the diffuse coefficient of each channel, 0 to 1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="344"/>
        <source>Od: the object&apos;s diffuse colour, 0 to 1 per channel</source>
        <translation>Od: the object&apos;s diffuse colour, 0 to 1 per channel</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="346"/>
        <source>Ke: the light the object gives off by itself, 0 to 255 per channel (added to every lit point)</source>
        <translation>Ke: the light the object gives off by itself, 0 to 255 per channel (added to every lit point)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="350"/>
        <source>ks: the specular coefficient, 0 to 1</source>
        <translation>ks: the specular coefficient, 0 to 1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="352"/>
        <source>n: the specular exponent (larger: a smaller, sharper highlight)</source>
        <translation>n: the specular exponent (larger: a smaller, sharper highlight)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="356"/>
        <source>Shading</source>
        <translation>Shading</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="359"/>
        <source>Phong (per pixel)</source>
        <translation>Phong (per pixel)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="360"/>
        <source>Gouraud (per vertex)</source>
        <translation>Gouraud (per vertex)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="361"/>
        <source>Flat (per triangle)</source>
        <translation>Flat (per triangle)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="362"/>
        <source>Painter&apos;s algorithm (flat, no depth test)</source>
        <translation>Painter&apos;s algorithm (flat, no depth test)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="372"/>
        <source>Two-sided lighting</source>
        <translation>Two-sided lighting</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="373"/>
        <source>On (the course&apos;s rule): where V.N &lt; 0 the normal is turned round, so the back of a surface is lit like its front. Off: one-sided, the back keeps a normal pointing away</source>
        <translation>On (the course&apos;s rule): where V.N &lt; 0 the normal is turned round, so the back of a surface is lit like its front. Off: one-sided, the back keeps a normal pointing away</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="376"/>
        <source>Blinn-Phong highlight</source>
        <translation>Blinn-Phong highlight</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="377"/>
        <source>The highlight with the half vector H = (L + V)/|L + V| instead of Phong&apos;s reflection R: (N.H)^n instead of (R.V)^n</source>
        <translation>The highlight with the half vector H = (L + V)/|L + V| instead of Phong&apos;s reflection R: (N.H)^n instead of (R.V)^n</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="441"/>
        <source>Add light %1</source>
        <translation>Add light %1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="448"/>
        <source>Remove light %1</source>
        <translation>Remove light %1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="473"/>
        <source>&amp;Undo</source>
        <translation>&amp;Undo</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="476"/>
        <source>&amp;Redo</source>
        <translation>&amp;Redo</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="480"/>
        <source>&amp;Save Camera and Lighting</source>
        <translation>&amp;Save Camera and Lighting</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="483"/>
        <source>Write the edited camera and lighting to their files</source>
        <translation>Write the edited camera and lighting to their files</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="489"/>
        <source>&amp;Camera...</source>
        <translation>&amp;Camera...</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="491"/>
        <source>&amp;Lighting...</source>
        <translation>&amp;Lighting...</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="494"/>
        <source>Save &amp;As</source>
        <translation>Save &amp;As</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="543"/>
        <source>Light %1 of %2</source>
        <translation>Light %1 of %2</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="626"/>
        <source>Change %1</source>
        <translation>Change %1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="707"/>
        <source>A command file is shown: its scene is not edited here.</source>
        <translation>A command file is shown: its scene is not edited here.</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="713"/>
        <source>%1 of the %2 example</source>
        <translation>%1 of the %2 example</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="717"/>
        <source>built-in scene</source>
        <translation>built-in scene</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="721"/>
        <source>modified</source>
        <translation>modified</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="727"/>
        <source>Lighting</source>
        <translation>Lighting</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="737"/>
        <source>shading</source>
        <translation>shading</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="739"/>
        <source>two-sided lighting</source>
        <translation>two-sided lighting</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="741"/>
        <source>the highlight&apos;s model</source>
        <translation>the highlight&apos;s model</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="743"/>
        <source>directional</source>
        <translation>directional</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="746"/>
        <source>spot cutoff</source>
        <translation>spot cutoff</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="749"/>
        <source>spot exponent</source>
        <translation>spot exponent</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="752"/>
        <source>spot direction</source>
        <translation>spot direction</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="755"/>
        <source>attenuation</source>
        <translation>attenuation</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="765"/>
        <source>%1 of light %2</source>
        <translation>%1 of light %2</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="774"/>
        <source>The camera was not saved.</source>
        <translation>The camera was not saved.</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="774"/>
        <source>The lighting was not saved.</source>
        <translation>The lighting was not saved.</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="847"/>
        <source>the %1 example</source>
        <translation>the %1 example</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="852"/>
        <source>The camera has changes that are not saved (%1).</source>
        <translation>The camera has changes that are not saved (%1).</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="853"/>
        <source>The lighting has changes that are not saved (%1).</source>
        <translation>The lighting has changes that are not saved (%1).</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="773"/>
        <source>Save</source>
        <translation>Save</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="829"/>
        <source>Save Camera As</source>
        <translation>Save Camera As</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="829"/>
        <source>Save Lighting As</source>
        <translation>Save Lighting As</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="849"/>
        <source>the built-in scene</source>
        <translation>the built-in scene</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="851"/>
        <source>Unsaved changes</source>
        <translation>Unsaved changes</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="858"/>
        <source>Save them?</source>
        <translation>Save them?</translation>
    </message>
</context>
<context>
    <name>rasterlab::Inspection</name>
    <message>
        <location filename="../views/inspection.cpp" line="191"/>
        <location filename="../views/inspection.cpp" line="193"/>
        <source>end of frame</source>
        <translation>end of frame</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="192"/>
        <source>start of frame: nothing drawn yet</source>
        <translation>start of frame: nothing drawn yet</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="197"/>
        <source>triangle %1 of %2</source>
        <translation>triangle %1 of %2</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="200"/>
        <source>scanline %1</source>
        <translation>scanline %1</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="203"/>
        <source>no pixel on it</source>
        <translation>no pixel on it</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="203"/>
        <source>span [%1, %2)</source>
        <translation>span [%1, %2)</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="205"/>
        <source>pixel %1</source>
        <translation>pixel %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::MainWindow</name>
    <message>
        <location filename="../app/window/main_window.cpp" line="68"/>
        <source>Open Camera</source>
        <translation>Open Camera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="70"/>
        <source>Open Lighting</source>
        <translation>Open Lighting</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="72"/>
        <source>Open Object</source>
        <translation>Open Object</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="80"/>
        <source>Camera files (*.cfg *.txt);;All files (*)</source>
        <translation>Camera files (*.cfg *.txt);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="82"/>
        <source>Lighting files (*.txt *.lux);;All files (*)</source>
        <translation>Lighting files (*.txt *.lux);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="84"/>
        <source>Objects (*.byu *.txt);;All files (*)</source>
        <translation>Objects (*.byu *.txt);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="31"/>
        <source>Detect from the file</source>
        <translation>Detect from the file</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="93"/>
        <source>flat</source>
        <translation>flat</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="95"/>
        <location filename="../app/window/main_window_export.cpp" line="70"/>
        <source>Gouraud</source>
        <translation>Gouraud</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="97"/>
        <location filename="../app/window/main_window_export.cpp" line="70"/>
        <source>Phong</source>
        <translation>Phong</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="99"/>
        <source>painter&apos;s-algorithm flat</source>
        <translation>painter&apos;s-algorithm flat</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="108"/>
        <source>%1 (built in)</source>
        <translation>%1 (built in)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="116"/>
        <source>RasterLab</source>
        <translation>RasterLab</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="172"/>
        <source>Stopped at a breakpoint: %1</source>
        <translation>Stopped at a breakpoint: %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="211"/>
        <location filename="../app/window/main_window_export.cpp" line="122"/>
        <location filename="../app/window/main_window_export.cpp" line="159"/>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="212"/>
        <source>Stop preparing the stepping of this frame</source>
        <translation>Stop preparing the stepping of this frame</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="216"/>
        <source>cancelled</source>
        <translation>cancelled</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="274"/>
        <source>Stepping</source>
        <translation>Stepping</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="298"/>
        <source>Edit</source>
        <translation>Edit</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="305"/>
        <source>Breakpoints</source>
        <translation>Breakpoints</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="311"/>
        <source>Animation</source>
        <translation>Animation</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="330"/>
        <source>1 Camera basis</source>
        <translation>1 Camera basis</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="302"/>
        <source>7 Pixel inspector (lighting)</source>
        <translation>7 Pixel inspector (lighting)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="337"/>
        <source>2 View coordinates (vertices)</source>
        <translation>2 View coordinates (vertices)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="339"/>
        <source>3 Normals</source>
        <translation>3 Normals</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="341"/>
        <source>4 Projection</source>
        <translation>4 Projection</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="333"/>
        <source>5 Scan conversion</source>
        <translation>5 Scan conversion</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="347"/>
        <source>5b Trapezoids</source>
        <translation>5b Trapezoids</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="351"/>
        <source>6 Z-buffer</source>
        <translation>6 Z-buffer</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="48"/>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="167"/>
        <source>&amp;Animation Frames...</source>
        <translation>&amp;Animation Frames...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="351"/>
        <source>P&amp;ainter&apos;s algorithm (flat, far to near, no depth test)</source>
        <translation>P&amp;ainter&apos;s algorithm (flat, far to near, no depth test)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1120"/>
        <source>step forward, back (on the image, or anywhere in presentation mode)</source>
        <translation>step forward, back (on the image, or anywhere in presentation mode)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1122"/>
        <source>Space</source>
        <translation>Space</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1122"/>
        <source>play / pause (on the image, or anywhere in presentation mode)</source>
        <translation>play / pause (on the image, or anywhere in presentation mode)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1128"/>
        <source>let go of the picked pixel (on the image)</source>
        <translation>let go of the picked pixel (on the image)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1129"/>
        <source>presentation mode on / off</source>
        <translation>presentation mode on / off</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1135"/>
        <source>fill the window with the panel under the pointer (in the lecture layout, the stage&apos;s), and back</source>
        <translation>fill the window with the panel under the pointer (in the lecture layout, the stage&apos;s), and back</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1139"/>
        <source>save, undo, redo</source>
        <translation>save, undo, redo</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="57"/>
        <source>Open &amp;Camera...</source>
        <translation>Open &amp;Camera...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="137"/>
        <source>Draw with the Plain Divide</source>
        <translation>Draw with the Plain Divide</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="59"/>
        <source>Ctrl+Shift+C</source>
        <translation>Ctrl+Shift+C</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="61"/>
        <source>Open &amp;Lighting...</source>
        <translation>Open &amp;Lighting...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="62"/>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="64"/>
        <source>Open Command &amp;File...</source>
        <translation>Open Command &amp;File...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="65"/>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="67"/>
        <source>Open &amp;Recent</source>
        <translation>Open &amp;Recent</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="69"/>
        <source>&amp;Default Scene</source>
        <translation>&amp;Default Scene</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="107"/>
        <source>&amp;Camera</source>
        <translation>&amp;Camera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="119"/>
        <source>&amp;Lighting</source>
        <translation>&amp;Lighting</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="135"/>
        <source>&amp;Export PNG...</source>
        <translation>&amp;Export PNG...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="136"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="138"/>
        <source>Export &amp;More</source>
        <translation>Export &amp;More</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="141"/>
        <source>Image as &amp;Displayed...</source>
        <translation>Image as &amp;Displayed...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="142"/>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="144"/>
        <source>&amp;Colour Buffer at the Cursor...</source>
        <translation>&amp;Colour Buffer at the Cursor...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="146"/>
        <source>D&amp;epth Buffer at the Cursor...</source>
        <translation>D&amp;epth Buffer at the Cursor...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="148"/>
        <source>&amp;Normal Buffer...</source>
        <translation>&amp;Normal Buffer...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="149"/>
        <source>A &amp;View as Displayed</source>
        <translation>A &amp;View as Displayed</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="153"/>
        <source>Export View</source>
        <translation>Export View</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="165"/>
        <source>&amp;Stepping Sequence...</source>
        <translation>&amp;Stepping Sequence...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="99"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="89"/>
        <source>Compare with &amp;Image...</source>
        <translation>Compare with &amp;Image...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="92"/>
        <source>A PNG of your own renderer against this scene&apos;s render, with the likely mistakes</source>
        <translation>A PNG of your own renderer against this scene&apos;s render, with the likely mistakes</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="94"/>
        <source>Check My &amp;Renderer...</source>
        <translation>Check My &amp;Renderer...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="96"/>
        <source>Your own renderer&apos;s stages, each held to the lecture&apos;s over the stage protocol</source>
        <translation>Your own renderer&apos;s stages, each held to the lecture&apos;s over the stage protocol</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="158"/>
        <source>Shading Side &amp;by Side...</source>
        <translation>Shading Side &amp;by Side...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="160"/>
        <source>Export Shading Side by Side</source>
        <translation>Export Shading Side by Side</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="172"/>
        <source>&amp;Edit</source>
        <translation>&amp;Edit</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="178"/>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="182"/>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Fit to Window</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="186"/>
        <source>&amp;Actual Size</source>
        <translation>&amp;Actual Size</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="188"/>
        <source>Zoom &amp;In</source>
        <translation>Zoom &amp;In</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="192"/>
        <source>Zoom &amp;Out</source>
        <translation>Zoom &amp;Out</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="202"/>
        <source>Reset &amp;Layout</source>
        <translation>Reset &amp;Layout</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="204"/>
        <source>Fill the &amp;Window with a Panel</source>
        <translation>Fill the &amp;Window with a Panel</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="208"/>
        <source>The panel with the focus or under the mouse (the image, from the image) over the whole window; again, the layout back</source>
        <translation>The panel with the focus or under the mouse (the image, from the image) over the whole window; again, the layout back</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="216"/>
        <source>&amp;Presentation Mode</source>
        <translation>&amp;Presentation Mode</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="221"/>
        <source>Larger text, thicker overlays, high contrast; the clicker&apos;s keys step (F5 or Esc)</source>
        <translation>Larger text, thicker overlays, high contrast; the clicker&apos;s keys step (F5 or Esc)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="223"/>
        <source>&amp;Lecture Layout</source>
        <translation>&amp;Lecture Layout</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="229"/>
        <source>In presentation mode, the stage being stepped fills the screen, the image beside it once something is drawn; off, your own layout (F7)</source>
        <translation>In presentation mode, the stage being stepped fills the screen, the image beside it once something is drawn; off, your own layout (F7)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="232"/>
        <source>Live &amp;Edits in Presentation</source>
        <translation>Live &amp;Edits in Presentation</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="237"/>
        <source>The Edit panel stays on screen in presentation mode: the light and the material change in front of the class (F9)</source>
        <translation>The Edit panel stays on screen in presentation mode: the light and the material change in front of the class (F9)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="251"/>
        <source>&amp;Text Size</source>
        <translation>&amp;Text Size</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="253"/>
        <source>&amp;Larger</source>
        <translation>&amp;Larger</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="256"/>
        <source>&amp;Smaller</source>
        <translation>&amp;Smaller</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="259"/>
        <source>&amp;Normal Size</source>
        <translation>&amp;Normal Size</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="271"/>
        <source>The System&apos;s</source>
        <translation>The System&apos;s</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="290"/>
        <source>S&amp;tep</source>
        <translation>S&amp;tep</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="314"/>
        <source>Pick the Pixel Under the &amp;Mouse</source>
        <translation>Pick the Pixel Under the &amp;Mouse</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="315"/>
        <source>Ctrl+G</source>
        <translation>Ctrl+G</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="344"/>
        <source>&amp;Shading</source>
        <translation>&amp;Shading</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="348"/>
        <source>&amp;Phong (per pixel)</source>
        <translation>&amp;Phong (per pixel)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="349"/>
        <source>&amp;Gouraud (per vertex)</source>
        <translation>&amp;Gouraud (per vertex)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="350"/>
        <source>&amp;Flat (per triangle)</source>
        <translation>&amp;Flat (per triangle)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="392"/>
        <source>Pro&amp;jection</source>
        <translation>Pro&amp;jection</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="397"/>
        <source>&amp;Clip at the Near Plane (nothing behind the eye is divided)</source>
        <translation>&amp;Clip at the Near Plane (nothing behind the eye is divided)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="399"/>
        <source>&amp;Plain Divide, No Clipping (seed 000 as written; seed 001&apos;s HW2)</source>
        <translation>&amp;Plain Divide, No Clipping (seed 000 as written; seed 001&apos;s HW2)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="401"/>
        <source>&amp;Same Side (clip only triangles that cross the eye plane)</source>
        <translation>&amp;Same Side (clip only triangles that cross the eye plane)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="709"/>
        <source>Every triangle is behind the camera (is N pointing away from the object?), so clipping at the near plane leaves nothing to draw. Seed 000&apos;s formula divides by z anyway: it would draw %1 of the %2 triangles as the object&apos;s point reflection through the eye, turned half a turn on the screen, and the z-buffer (keeping the smallest z) would keep the side farthest from the camera. The projection view&apos;s side view shows the eye, N and the object.</source>
        <translation>Every triangle is behind the camera (is N pointing away from the object?), so clipping at the near plane leaves nothing to draw. Seed 000&apos;s formula divides by z anyway: it would draw %1 of the %2 triangles as the object&apos;s point reflection through the eye, turned half a turn on the screen, and the z-buffer (keeping the smallest z) would keep the side farthest from the camera. The projection view&apos;s side view shows the eye, N and the object.</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1011"/>
        <source>not kept</source>
        <translation>not kept</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1103"/>
        <source>&lt;p&gt;It follows the courses it was made for: the computer graphics course projects of UFPE and UFRPE (Phong shading with a z-buffer, and its flat-shading variant with the painter&apos;s algorithm), the assignment “HW2: 3D Rasterizer”, the per-frame rendering pipeline of an animation course, and Prof. Jonh Edson R. de Carvalho&apos;s lecture slides on illumination models (“Modelos de Iluminação”).&lt;/p&gt;</source>
        <translation>&lt;p&gt;It follows the courses it was made for: the computer graphics course projects of UFPE and UFRPE (Phong shading with a z-buffer, and its flat-shading variant with the painter&apos;s algorithm), the assignment “HW2: 3D Rasterizer”, the per-frame rendering pipeline of an animation course, and Prof. Jonh Edson R. de Carvalho&apos;s lecture slides on illumination models (“Modelos de Iluminação”).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1117"/>
        <source>step forward</source>
        <translation>step forward</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1118"/>
        <source>step back</source>
        <translation>step back</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1121"/>
        <source>play / pause</source>
        <translation>play / pause</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1123"/>
        <source>jump to the start / the end of the frame</source>
        <translation>jump to the start / the end of the frame</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1124"/>
        <source>continue to the next breakpoint</source>
        <translation>continue to the next breakpoint</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1125"/>
        <source>step by stage, triangle, scanline, span, pixel</source>
        <translation>step by stage, triangle, scanline, span, pixel</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1126"/>
        <source>show a stage&apos;s view</source>
        <translation>show a stage&apos;s view</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1127"/>
        <source>Click, arrows</source>
        <translation>Click, arrows</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1127"/>
        <source>pick a pixel, move it by one</source>
        <translation>pick a pixel, move it by one</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1131"/>
        <source>presentation mode: the lecture layout (the stage being stepped fills the screen) or your own layout</source>
        <translation>presentation mode: the lecture layout (the stage being stepped fills the screen) or your own layout</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1133"/>
        <source>presentation mode: the Edit panel on screen (live edits)</source>
        <translation>presentation mode: the Edit panel on screen (live edits)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1134"/>
        <source>F11, double-click on a panel&apos;s title</source>
        <translation>F11, double-click on a panel&apos;s title</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1138"/>
        <source>open, export the image, export it as displayed</source>
        <translation>open, export the image, export it as displayed</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1164"/>
        <source>Keyboard Shortcuts</source>
        <translation>Keyboard Shortcuts</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="369"/>
        <source>&amp;Rasterization Rules</source>
        <translation>&amp;Rasterization Rules</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="374"/>
        <source>&amp;Course (seed 000: whole-pixel vertices, screen-space interpolation)</source>
        <translation>&amp;Course (seed 000: whole-pixel vertices, screen-space interpolation)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="376"/>
        <source>&amp;GPU-like (1/256-pixel vertices, pixel centres, top-left rule, perspective-correct)</source>
        <translation>&amp;GPU-like (1/256-pixel vertices, pixel centres, top-left rule, perspective-correct)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="378"/>
        <source>&amp;HW2 (seed 001&apos;s reference images)</source>
        <translation>&amp;HW2 (seed 001&apos;s reference images)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="415"/>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="421"/>
        <source>&amp;User Guide</source>
        <translation>&amp;User Guide</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="427"/>
        <source>The user guide is not installed</source>
        <translation>The user guide is not installed</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="429"/>
        <source>&amp;About RasterLab</source>
        <translation>&amp;About RasterLab</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="283"/>
        <source>Messages</source>
        <translation>Messages</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="288"/>
        <source>Scene</source>
        <translation>Scene</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="308"/>
        <source>Accuracy</source>
        <translation>Accuracy</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="683"/>
        <location filename="../app/window/main_window_export.cpp" line="35"/>
        <location filename="../app/window/main_window_export.cpp" line="133"/>
        <location filename="../app/window/main_window_export.cpp" line="175"/>
        <location filename="../app/window/main_window_export.cpp" line="209"/>
        <source>%1: cannot export the image: %2</source>
        <translation>%1: cannot export the image: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="27"/>
        <source>nothing has been rendered yet</source>
        <translation>nothing has been rendered yet</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="30"/>
        <source>Exported %1</source>
        <translation>Exported %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="736"/>
        <source>rendering...</source>
        <translation>rendering...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="736"/>
        <source>%1, rendering...</source>
        <translation>%1, rendering...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="734"/>
        <location filename="../app/window/main_window.cpp" line="974"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="49"/>
        <source>&amp;Open...</source>
        <translation>&amp;Open...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="52"/>
        <source>A course camera, lighting or object file, or a command file</source>
        <translation>A course camera, lighting or object file, or a command file</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="53"/>
        <source>Open O&amp;bject...</source>
        <translation>Open O&amp;bject...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="55"/>
        <source>Ctrl+Shift+B</source>
        <translation>Ctrl+Shift+B</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="105"/>
        <source>Course File La&amp;youts</source>
        <translation>Course File La&amp;youts</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="180"/>
        <source>Image &amp;Zoom</source>
        <translation>Image &amp;Zoom</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="198"/>
        <source>Pa&amp;nels</source>
        <translation>Pa&amp;nels</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="213"/>
        <source>I&amp;mage</source>
        <translation>I&amp;mage</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="266"/>
        <source>Lan&amp;guage</source>
        <translation>Lan&amp;guage</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="299"/>
        <source>Step B&amp;y</source>
        <translation>Step B&amp;y</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="301"/>
        <source>S&amp;tage</source>
        <translation>S&amp;tage</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="416"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Keyboard Shortcuts</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="402"/>
        <source>Presentation mode: F5 or Esc to leave; Page Down, Right and Space step and play</source>
        <translation>Presentation mode: F5 or Esc to leave; Page Down, Right and Space step and play</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="666"/>
        <source>%1[*] - RasterLab</source>
        <translation>%1[*] - RasterLab</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="744"/>
        <source>Preparing the stepping of this frame</source>
        <translation>Preparing the stepping of this frame</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="744"/>
        <source>Rendering</source>
        <translation>Rendering</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="917"/>
        <source>Error: %1</source>
        <translation>Error: %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="941"/>
        <source>Files</source>
        <translation>Files</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="944"/>
        <source>Command file</source>
        <translation>Command file</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="945"/>
        <source>Image</source>
        <translation>Image</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="947"/>
        <source>%1 vertices, %2 triangles in %3 draws; %4 x %5 pixels; %6 lights</source>
        <translation>%1 vertices, %2 triangles in %3 draws; %4 x %5 pixels; %6 lights</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="957"/>
        <source>Camera</source>
        <translation>Camera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="958"/>
        <source>Lighting</source>
        <translation>Lighting</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="959"/>
        <source>Object</source>
        <translation>Object</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="961"/>
        <source>%1 vertices, %2 triangles; %3 x %4 pixels, %5 shading</source>
        <translation>%1 vertices, %2 triangles; %3 x %4 pixels, %5 shading</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="268"/>
        <location filename="../app/window/main_window.cpp" line="968"/>
        <source>Stages</source>
        <translation>Stages</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="106"/>
        <source>%1 (the %2 example)</source>
        <translation>%1 (the %2 example)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="301"/>
        <source>7 Pixel inspector</source>
        <translation>7 Pixel inspector</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="330"/>
        <source>1 Camera</source>
        <translation>1 Camera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="333"/>
        <source>5 Scan</source>
        <translation>5 Scan</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="336"/>
        <source>2 View</source>
        <translation>2 View</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="344"/>
        <source>4b Clipping</source>
        <translation>4b Clipping</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="346"/>
        <source>4b Near-plane clipping (seed 002)</source>
        <translation>4b Near-plane clipping (seed 002)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="349"/>
        <source>5b Trapezoids: the scan of seed 002</source>
        <translation>5b Trapezoids: the scan of seed 002</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="354"/>
        <source>Painter</source>
        <translation>Painter</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="355"/>
        <source>Painter&apos;s algorithm (seed 004)</source>
        <translation>Painter&apos;s algorithm (seed 004)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="363"/>
        <source>Use the Fitted Lighting</source>
        <translation>Use the Fitted Lighting</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="371"/>
        <source>Compare</source>
        <translation>Compare</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="371"/>
        <source>Compare with their image</source>
        <translation>Compare with their image</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="939"/>
        <source>Lesson: %1</source>
        <translation>Lesson: %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="975"/>
        <source>skipped: %1</source>
        <translation>skipped: %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="978"/>
        <source>Counts</source>
        <translation>Counts</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="979"/>
        <source>Triangles clipped at the near plane: %1; behind the camera: %2&lt;br&gt;</source>
        <translation>Triangles clipped at the near plane: %1; behind the camera: %2&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="982"/>
        <source>Zero-area triangles: %1 in view space, %2 on screen&lt;br&gt;</source>
        <translation>Zero-area triangles: %1 in view space, %2 on screen&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="985"/>
        <source>Fragments tested: %1; written: %2; rejected: %3&lt;br&gt;</source>
        <translation>Fragments tested: %1; written: %2; rejected: %3&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="989"/>
        <source>Pixels shaded: %1; normals turned toward the viewer: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; clamped at 255: %5</source>
        <translation>Pixels shaded: %1; normals turned toward the viewer: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; clamped at 255: %5</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1013"/>
        <source>empty (+inf)</source>
        <translation>empty (+inf)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1014"/>
        <source>x %1, y %2   RGB (%3, %4, %5)   depth %6</source>
        <translation>x %1, y %2   RGB (%3, %4, %5)   depth %6</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1030"/>
        <source>Open Command File</source>
        <translation>Open Command File</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1031"/>
        <source>Command files (*.txt);;All files (*)</source>
        <translation>Command files (*.txt);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1037"/>
        <source>Open</source>
        <translation>Open</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1037"/>
        <source>Scene files (*.byu *.cfg *.txt *.lux);;All files (*)</source>
        <translation>Scene files (*.byu *.cfg *.txt *.lux);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1047"/>
        <source>Export PNG</source>
        <translation>Export PNG</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1047"/>
        <location filename="../app/window/main_window_actions.cpp" line="154"/>
        <location filename="../app/window/main_window_actions.cpp" line="161"/>
        <location filename="../app/window/main_window_export.cpp" line="198"/>
        <location filename="../app/window/main_window_export.cpp" line="206"/>
        <source>PNG images (*.png)</source>
        <translation>PNG images (*.png)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1052"/>
        <source>Compare with Image</source>
        <translation>Compare with Image</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1053"/>
        <source>PNG images (*.png);;All files (*)</source>
        <translation>PNG images (*.png);;All files (*)</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/window/main_window.cpp" line="1082"/>
        <source>Compared %1 with our render: %n pixel(s) differ</source>
        <translation>
            <numerusform>Compared %1 with our render: %n pixel differs</numerusform>
            <numerusform>Compared %1 with our render: %n pixels differ</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1090"/>
        <source>About RasterLab</source>
        <translation>About RasterLab</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1096"/>
        <source>Released under the MIT License, whose text is in %1.</source>
        <translation>Released under the MIT License, whose text is in %1.</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1098"/>
        <source>Released under the MIT License.</source>
        <translation>Released under the MIT License.</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1099"/>
        <source>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;The classic software rasterization pipeline, stage by stage: camera basis, view transform, normals, projection, scan conversion, depth test and shading.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;The classic software rasterization pipeline, stage by stage: camera basis, view transform, normals, projection, scan conversion, depth test and shading.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1141"/>
        <source>the panels&apos; text larger, smaller, its normal size</source>
        <translation>the panels&apos; text larger, smaller, its normal size</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1143"/>
        <source>the image: zoom in, zoom out, fit, actual size (and the wheel)</source>
        <translation>the image: zoom in, zoom out, fit, actual size (and the wheel)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1156"/>
        <source>These keys act wherever the focus is, a number box included (it keeps its digits and its up and down arrows).</source>
        <translation>These keys act wherever the focus is, a number box included (it keeps its digits and its up and down arrows).</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="42"/>
        <source>%1: cannot export the depth buffer: %2</source>
        <translation>%1: cannot export the depth buffer: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="47"/>
        <source>%1: cannot export the normal buffer: %2</source>
        <translation>%1: cannot export the normal buffer: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="63"/>
        <source>%1: cannot export the shadings side by side: %2</source>
        <translation>%1: cannot export the shadings side by side: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="65"/>
        <source>it needs a course scene</source>
        <translation>it needs a course scene</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="70"/>
        <source>Flat</source>
        <translation>Flat</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="104"/>
        <source>%1: cannot export the view: there is no view %2</source>
        <translation>%1: cannot export the view: there is no view %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="107"/>
        <source>%1: cannot export the view: %2</source>
        <translation>%1: cannot export the view: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="113"/>
        <source>%1: cannot export the steps: the frame cannot be stepped through yet</source>
        <translation>%1: cannot export the steps: the frame cannot be stepped through yet</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="117"/>
        <location filename="../app/window/main_window_export.cpp" line="151"/>
        <source>%1: cannot create the folder</source>
        <translation>%1: cannot create the folder</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="122"/>
        <source>Exporting the steps...</source>
        <translation>Exporting the steps...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="144"/>
        <source>Exported %1 images to %2</source>
        <translation>Exported %1 images to %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="159"/>
        <source>Exporting the animation&apos;s frames...</source>
        <translation>Exporting the animation&apos;s frames...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="184"/>
        <source>%1: cannot render the frame: %2</source>
        <translation>%1: cannot render the frame: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="185"/>
        <source>Exported %1 frames to %2</source>
        <translation>Exported %1 frames to %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="191"/>
        <source>Folder for the Animation&apos;s Frames</source>
        <translation>Folder for the Animation&apos;s Frames</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="196"/>
        <source>Export the Image as Displayed</source>
        <translation>Export the Image as Displayed</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="205"/>
        <source>Export a Buffer</source>
        <translation>Export a Buffer</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="219"/>
        <source>Folder for the Numbered Images</source>
        <translation>Folder for the Numbered Images</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="223"/>
        <source>Stepping Sequence</source>
        <translation>Stepping Sequence</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="224"/>
        <source>At most how many images (one per step, at the current granularity)?</source>
        <translation>At most how many images (one per step, at the current granularity)?</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_files.cpp" line="118"/>
        <source>%1: no course camera, lighting, object or command file in this folder</source>
        <translation>%1: no course camera, lighting, object or command file in this folder</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_files.cpp" line="122"/>
        <source>%1: no such file</source>
        <translation>%1: no such file</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_files.cpp" line="140"/>
        <source>%1: not a course camera, lighting or object file, nor a command file (expected a .byu object, a camera or lighting in one of the course layouts, or png/xyz/tri commands)</source>
        <translation>%1: not a course camera, lighting or object file, nor a command file (expected a .byu object, a camera or lighting in one of the course layouts, or png/xyz/tri commands)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_files.cpp" line="180"/>
        <source>&amp;Clear the List</source>
        <translation>&amp;Clear the List</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_files.cpp" line="251"/>
        <source>%1 changed on disk: read again</source>
        <translation>%1 changed on disk: read again</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_docks.cpp" line="205"/>
        <source>%1 fills the window: F11 or a double-click on its title gives the layout back</source>
        <translation>%1 fills the window: F11 or a double-click on its title gives the layout back</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_docks.cpp" line="206"/>
        <source>The image</source>
        <translation>The image</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="80"/>
        <source>E&amp;xamples</source>
        <translation>E&amp;xamples</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="90"/>
        <source>Open Lesso&amp;n...</source>
        <translation>Open Lesso&amp;n...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="91"/>
        <source>Ctrl+Alt+O</source>
        <translation>Ctrl+Alt+O</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="93"/>
        <source>A lesson file (.rasterlab): a scene with its stepping, picked pixel, breakpoints, zoom and docks</source>
        <translation>A lesson file (.rasterlab): a scene with its stepping, picked pixel, breakpoints, zoom and docks</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="95"/>
        <source>Save Lesson &amp;As...</source>
        <translation>Save Lesson &amp;As...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="96"/>
        <source>Ctrl+Alt+S</source>
        <translation>Ctrl+Alt+S</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="98"/>
        <source>Recent Lesso&amp;ns</source>
        <translation>Recent Lesso&amp;ns</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="124"/>
        <source>Open Lesson</source>
        <translation>Open Lesson</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="125"/>
        <source>Lessons (*.rasterlab);;All files (*)</source>
        <translation>Lessons (*.rasterlab);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="130"/>
        <source>Save Lesson</source>
        <translation>Save Lesson</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="131"/>
        <source>Lessons (*.rasterlab)</source>
        <translation>Lessons (*.rasterlab)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="134"/>
        <source>Saved the lesson to %1</source>
        <translation>Saved the lesson to %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="139"/>
        <location filename="../app/window/main_window_lessons.cpp" line="152"/>
        <source>there is no example named &apos;%1&apos; (examples: %2)</source>
        <translation>there is no example named &apos;%1&apos; (examples: %2)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="167"/>
        <source>the %1 was not restored, the one shown stays: %2</source>
        <translation>the %1 was not restored, the one shown stays: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="170"/>
        <source>camera</source>
        <translation>camera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="171"/>
        <source>lighting</source>
        <translation>lighting</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="172"/>
        <source>object</source>
        <translation>object</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="175"/>
        <source>the command file was not restored, the scene shown stays: %1</source>
        <translation>the command file was not restored, the scene shown stays: %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="224"/>
        <source>The lesson opened, but not all of it: see the Messages dock</source>
        <translation>The lesson opened, but not all of it: see the Messages dock</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="374"/>
        <source>%1: cannot save the lesson: %2</source>
        <translation>%1: cannot save the lesson: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_check.cpp" line="20"/>
        <source>Check</source>
        <translation>Check</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_check.cpp" line="21"/>
        <source>Check your renderer</source>
        <translation>Check your renderer</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_check.cpp" line="29"/>
        <source>Cannot write their frame to %1</source>
        <translation>Cannot write their frame to %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="160"/>
        <source>Lecture layout: the stage being stepped fills the screen (F7: your own layout)</source>
        <translation>Lecture layout: the stage being stepped fills the screen (F7: your own layout)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="162"/>
        <source>Your own layout (F7: the lecture layout again)</source>
        <translation>Your own layout (F7: the lecture layout again)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="280"/>
        <source>|N| = %1 · U = %2 · V = %3 · N = %4</source>
        <translation>|N| = %1 · U = %2 · V = %3 · N = %4</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="285"/>
        <source>%1 vertices: %2 in front of the camera, %3 behind</source>
        <translation>%1 vertices: %2 in front of the camera, %3 behind</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="294"/>
        <source>%1 triangle normals: %2 front faces, %3 back faces · %4 vertex normals</source>
        <translation>%1 triangle normals: %2 front faces, %3 back faces · %4 vertex normals</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="303"/>
        <source> · triangle %1: n = %2</source>
        <translation> · triangle %1: n = %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="309"/>
        <source>%1 triangles: %2 inside, %3 clipped, %4 behind · near plane w = %5</source>
        <translation>%1 triangles: %2 inside, %3 clipped, %4 behind · near plane w = %5</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="315"/>
        <source>%1 triangles → %2 spans, %3 pixels covered</source>
        <translation>%1 triangles → %2 spans, %3 pixels covered</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="320"/>
        <source>%1 fragments tested, %2 written, %3 rejected</source>
        <translation>%1 fragments tested, %2 written, %3 rejected</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="324"/>
        <source> · z kept from %1 to %2</source>
        <translation> · z kept from %1 to %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="328"/>
        <source>%1 pixels shaded · N·L &lt; 0: %2 · R·V &lt; 0: %3 · clamped at 255: %4</source>
        <translation>%1 pixels shaded · N·L &lt; 0: %2 · R·V &lt; 0: %3 · clamped at 255: %4</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="398"/>
        <source>Text size %1 %</source>
        <translation>Text size %1 %</translation>
    </message>
</context>
<context>
    <name>rasterlab::NearClipView</name>
    <message>
        <location filename="../views/near_clip_view.cpp" line="77"/>
        <source>wholly in front</source>
        <translation>wholly in front</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="79"/>
        <source>clipped</source>
        <translation>clipped</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="81"/>
        <source>wholly behind</source>
        <translation>wholly behind</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="83"/>
        <source>outside a clip plane</source>
        <translation>outside a clip plane</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="85"/>
        <source>culled</source>
        <translation>culled</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="87"/>
        <source>hidden back face</source>
        <translation>hidden back face</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="89"/>
        <source>beyond the guard band</source>
        <translation>beyond the guard band</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="91"/>
        <source>not finite</source>
        <translation>not finite</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="207"/>
        <source>No triangle to show: select one, step into the frame, or choose one in the list.</source>
        <translation>No triangle to show: select one, step into the frame, or choose one in the list.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="267"/>
        <source>side view: w across (view z for the course camera), view %1 up</source>
        <translation>side view: w across (view z for the course camera), view %1 up</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="394"/>
        <source>w = near = %1</source>
        <translation>w = near = %1</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="397"/>
        <source>the plane w = near = %1 is far to the left, out of the picture</source>
        <translation>the plane w = near = %1 is far to the left, out of the picture</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="404"/>
        <source>eye</source>
        <translation>eye</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="407"/>
        <source>the eye (w = 0) is far to the left, out of the picture</source>
        <translation>the eye (w = 0) is far to the left, out of the picture</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="415"/>
        <source>on the screen (pixels)</source>
        <translation>on the screen (pixels)</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="419"/>
        <source>The last step projects the triangles drawn.</source>
        <translation>The last step projects the triangles drawn.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="465"/>
        <source>zoomed: x %1 to %2, y %3 to %4</source>
        <translation>zoomed: x %1 to %2, y %3 to %4</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="498"/>
        <source>image %1 × %2</source>
        <translation>image %1 × %2</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="503"/>
        <source>Nothing drawn.</source>
        <translation>Nothing drawn.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="511"/>
        <source>The triangle shown: the one selected, or one the near plane cut</source>
        <translation>The triangle shown: the one selected, or one the near plane cut</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="514"/>
        <source>y up</source>
        <translation>y up</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="515"/>
        <source>x up</source>
        <translation>x up</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="516"/>
        <source>Which view axis the side view draws upward</source>
        <translation>Which view axis the side view draws upward</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="517"/>
        <source>Back</source>
        <translation>Back</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="519"/>
        <source>Next</source>
        <translation>Next</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="521"/>
        <source>All</source>
        <translation>All</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="587"/>
        <source>The triangle selected (or being drawn)</source>
        <translation>The triangle selected (or being drawn)</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="595"/>
        <source>triangle %1: %2</source>
        <translation>triangle %1: %2</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="689"/>
        <source>step %1 of %2</source>
        <translation>step %1 of %2</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="699"/>
        <source>No frame yet.</source>
        <translation>No frame yet.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="700"/>
        <source>No triangle to show: select one or step into the frame.</source>
        <translation>No triangle to show: select one or step into the frame.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="702"/>
        <source>&lt;b&gt;Triangle %1&lt;/b&gt; of %2: %3</source>
        <translation>&lt;b&gt;Triangle %1&lt;/b&gt; of %2: %3</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="729"/>
        <source>The seed clips each triangle against the plane z = &amp;minus;&amp;epsilon;, P = [0, 0, &amp;minus;1, &amp;epsilon;], before the perspective divide (OpenGL&apos;s camera looks along &amp;minus;z). The projection stage clips against w = near in clip space, here near = %1, so P = %2 and a point A is kept when dot(P, A) = w &amp;minus; near &amp;ge; 0.</source>
        <translation>The seed clips each triangle against the plane z = &amp;minus;&amp;epsilon;, P = [0, 0, &amp;minus;1, &amp;epsilon;], before the perspective divide (OpenGL&apos;s camera looks along &amp;minus;z). The projection stage clips against w = near in clip space, here near = %1, so P = %2 and a point A is kept when dot(P, A) = w &amp;minus; near &amp;ge; 0.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="736"/>
        <source>For the course camera w is the view z: the camera looks along +z, and the plane is z = near, P = [0, 0, 1, &amp;minus;near].</source>
        <translation>For the course camera w is the view z: the camera looks along +z, and the plane is z = near, P = [0, 0, 1, &amp;minus;near].</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="739"/>
        <source>(Written out, the seed&apos;s P keeps z &amp;le; &amp;epsilon;; the plane z = &amp;minus;&amp;epsilon; it names is P = [0, 0, &amp;minus;1, &amp;minus;&amp;epsilon;]. Either way the plane lies a little in front of the eye, so no vertex drawn is divided by w = 0.)</source>
        <translation>(Written out, the seed&apos;s P keeps z &amp;le; &amp;epsilon;; the plane z = &amp;minus;&amp;epsilon; it names is P = [0, 0, &amp;minus;1, &amp;minus;&amp;epsilon;]. Either way the plane lies a little in front of the eye, so no vertex drawn is divided by w = 0.)</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="743"/>
        <source>A0 = %1, A1 = %2, A2 = %3 (view space).</source>
        <translation>A0 = %1, A1 = %2, A2 = %3 (view space).</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="747"/>
        <source>This scene does not clip against the near plane (the naive or same-side projection): the steps show what clipping would do.</source>
        <translation>This scene does not clip against the near plane (the naive or same-side projection): the steps show what clipping would do.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="752"/>
        <source>The draw&apos;s clip planes cut the triangle first; the polygon the stage drew may differ from the one here.</source>
        <translation>The draw&apos;s clip planes cut the triangle first; the polygon the stage drew may differ from the one here.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="759"/>
        <source>Vertex %1: dot(P, %1) = %2</source>
        <translation>Vertex %1: dot(P, %1) = %2</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="762"/>
        <source>kept, added to the output polygon as q%1.</source>
        <translation>kept, added to the output polygon as q%1.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="764"/>
        <source>behind the plane, left out.</source>
        <translation>behind the plane, left out.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="768"/>
        <source>Edge %1&amp;ndash;%2: dot(P, %1) = %3 and dot(P, %2) = %4 have the same sign: the edge does not cross the plane.</source>
        <translation>Edge %1&amp;ndash;%2: dot(P, %1) = %3 and dot(P, %2) = %4 have the same sign: the edge does not cross the plane.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="772"/>
        <source>Edge %1&amp;ndash;%2: dot(P, %1) = %3 and dot(P, %2) = %4 differ in sign: t = (0 &amp;minus; %5) / (%6 &amp;minus; %5) = %7, C = lerp(t, %1, %2) = %8, added as q%9.</source>
        <translation>Edge %1&amp;ndash;%2: dot(P, %1) = %3 and dot(P, %2) = %4 differ in sign: t = (0 &amp;minus; %5) / (%6 &amp;minus; %5) = %7, C = lerp(t, %1, %2) = %8, added as q%9.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="780"/>
        <source>(The stage computes the same point from %1, the end in front, with t&apos; = 1 &amp;minus; t = %2, so that the two triangles sharing the edge get it bit for bit.)</source>
        <translation>(The stage computes the same point from %1, the end in front, with t&apos; = 1 &amp;minus; t = %2, so that the two triangles sharing the edge get it bit for bit.)</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="791"/>
        <source>Output polygon: empty. The triangle lies wholly behind the plane: nothing is drawn.</source>
        <translation>Output polygon: empty. The triangle lies wholly behind the plane: nothing is drawn.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="797"/>
        <source>Output polygon, %1 vertices: %2.</source>
        <translation>Output polygon, %1 vertices: %2.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="801"/>
        <source>The triangle is wholly in front: untouched.</source>
        <translation>The triangle is wholly in front: untouched.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="808"/>
        <source>Four vertices: split along the diagonal q0&amp;ndash;q2 into the triangles q0 q1 q2 and q0 q2 q3, rendered separately.</source>
        <translation>Four vertices: split along the diagonal q0&amp;ndash;q2 into the triangles q0 q1 q2 and q0 q2 q3, rendered separately.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="811"/>
        <source>Three vertices: one triangle, nothing to split.</source>
        <translation>Three vertices: one triangle, nothing to split.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="813"/>
        <source>Fewer than three vertices: no triangle.</source>
        <translation>Fewer than three vertices: no triangle.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="816"/>
        <source>Then each vertex is projected and taken to pixels.</source>
        <translation>Then each vertex is projected and taken to pixels.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="819"/>
        <source>Nothing was drawn from this triangle (%1).</source>
        <translation>Nothing was drawn from this triangle (%1).</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="823"/>
        <source>Triangle %1: %2, %3, %4 (pixels)</source>
        <translation>Triangle %1: %2, %3, %4 (pixels)</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="830"/>
        <source>(%1 of the %2 triangles were drawn: %3.)</source>
        <translation>(%1 of the %2 triangles were drawn: %3.)</translation>
    </message>
</context>
<context>
    <name>rasterlab::NormalsView</name>
    <message>
        <location filename="../views/normals_model.cpp" line="164"/>
        <source>the draw is unlit: shading reads no normal</source>
        <translation>the draw is unlit: shading reads no normal</translation>
    </message>
    <message>
        <location filename="../views/normals_model.cpp" line="190"/>
        <source>the interpolated normal is zero</source>
        <translation>the interpolated normal is zero</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="36"/>
        <source>Triangle normals</source>
        <translation>Triangle normals</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="39"/>
        <source>Vertex normals</source>
        <translation>Vertex normals</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="42"/>
        <source>Only on triangles that are seen</source>
        <translation>Only on triangles that are seen</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="45"/>
        <source>Hairs only on the triangles that hold a pixel at the end of the frame, and on their corners</source>
        <translation>Hairs only on the triangles that hold a pixel at the end of the frame, and on their corners</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="48"/>
        <source>Normals by M (wrong)</source>
        <translation>Normals by M (wrong)</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="51"/>
        <source>Beside each triangle normal, the model normal carried by viewFromModel itself instead of its inverse transpose: it leaves the surface under a non-uniform scale (set one in the Animation panel)</source>
        <translation>Beside each triangle normal, the model normal carried by viewFromModel itself instead of its inverse transpose: it leaves the surface under a non-uniform scale (set one in the Animation panel)</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="74"/>
        <source>Per pixel at the stepping cursor, the unit normal shading uses there: the vertex normals interpolated with the pixel&apos;s barycentrics and normalised (the triangle&apos;s normal for flat shading), turned toward the viewer as the course does before lighting; shown as RGB = (n + 1) / 2. Red grows to the right, green upward, blue away from the camera: turned normals face the camera, so blue is mostly below 128. Black: no triangle.</source>
        <translation>Per pixel at the stepping cursor, the unit normal shading uses there: the vertex normals interpolated with the pixel&apos;s barycentrics and normalised (the triangle&apos;s normal for flat shading), turned toward the viewer as the course does before lighting; shown as RGB = (n + 1) / 2. Red grows to the right, green upward, blue away from the camera: turned normals face the camera, so blue is mostly below 128. Black: no triangle.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="89"/>
        <source>Mesh and normals</source>
        <translation>Mesh and normals</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="90"/>
        <source>Normal map</source>
        <translation>Normal map</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="284"/>
        <source>No frame yet.</source>
        <translation>No frame yet.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="290"/>
        <source>front faces %1</source>
        <translation>front faces %1</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="292"/>
        <location filename="../views/normals_view.cpp" line="296"/>
        <source>(%1 hidden, left out by culling)</source>
        <translation>(%1 hidden, left out by culling)</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="294"/>
        <source>back faces (n · pView &amp;gt; 0) %1</source>
        <translation>back faces (n · pView &amp;gt; 0) %1</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="299"/>
        <source>inconsistent winding: %1 triangles, %2 edges run the same way by two triangles</source>
        <translation>inconsistent winding: %1 triangles, %2 edges run the same way by two triangles</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="306"/>
        <source>%1% of the pixels seen are back faces: the surface is closed and its normals point inward in view space (the course&apos;s [U; V; N] mirrors, so a file wound counter-clockwise seen from outside turns over). Shading turns every normal toward the viewer: the image does not change.</source>
        <translation>%1% of the pixels seen are back faces: the surface is closed and its normals point inward in view space (the course&apos;s [U; V; N] mirrors, so a file wound counter-clockwise seen from outside turns over). Shading turns every normal toward the viewer: the image does not change.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="313"/>
        <source>No normals: %1.</source>
        <translation>No normals: %1.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="318"/>
        <source>triangle normals</source>
        <translation>triangle normals</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="319"/>
        <source>vertex normals</source>
        <translation>vertex normals</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="321"/>
        <source>length L = %1 (%2% of the mesh&apos;s size)</source>
        <translation>length L = %1 (%2% of the mesh&apos;s size)</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="326"/>
        <source>triangle normals carried by M itself (wrong)</source>
        <translation>triangle normals carried by M itself (wrong)</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="329"/>
        <source>on the %1 triangles seen and their corners</source>
        <translation>on the %1 triangles seen and their corners</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="332"/>
        <source>Large mesh: one triangle normal in %1 and one vertex normal in %2 are drawn; the selected triangle&apos;s always.</source>
        <translation>Large mesh: one triangle normal in %1 and one vertex normal in %2 are drawn; the selected triangle&apos;s always.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="339"/>
        <source>One triangle in %1 of the wireframe is drawn.</source>
        <translation>One triangle in %1 of the wireframe is drawn.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="356"/>
        <source>&lt;p&gt;&lt;b&gt;Normals by M, right and wrong&lt;/b&gt;: A = viewFromModel = viewFromWorld · M(t) · worldFromModel (M: the animation matrix, the identity when the animation is off). The model-space normal n = %1, det A = %2; the carried edges, made unit: e1 = A (P2 − P1) / |…| = %3, e2 = A (P3 − P1) / |…| = %4.&lt;br&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Normals by M, right and wrong&lt;/b&gt;: A = viewFromModel = viewFromWorld · M(t) · worldFromModel (M: the animation matrix, the identity when the animation is off). The model-space normal n = %1, det A = %2; the carried edges, made unit: e1 = A (P2 − P1) / |…| = %3, e2 = A (P3 − P1) / |…| = %4.&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="363"/>
        <source>Right: A&lt;sup&gt;−T&lt;/sup&gt; n, normalised = &lt;b&gt;%1&lt;/b&gt;; its dots with e1 and e2 are %2 and %3: perpendicular to the surface.&lt;br&gt;</source>
        <translation>Right: A&lt;sup&gt;−T&lt;/sup&gt; n, normalised = &lt;b&gt;%1&lt;/b&gt;; its dots with e1 and e2 are %2 and %3: perpendicular to the surface.&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="367"/>
        <source>Wrong: A n, normalised = &lt;b&gt;%1&lt;/b&gt;; its dots with e1 and e2 are %2 and %3: %4° off the surface&apos;s normal.&lt;/p&gt;</source>
        <translation>Wrong: A n, normalised = &lt;b&gt;%1&lt;/b&gt;; its dots with e1 and e2 are %2 and %3: %4° off the surface&apos;s normal.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="373"/>
        <source>&lt;p&gt;Here both agree: A has no non-uniform scale. Set a scale such as (2, 1, 1) in the Animation panel to see them part.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Here both agree: A has no non-uniform scale. Set a scale such as (2, 1, 1) in the Animation panel to see them part.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="381"/>
        <source>&lt;p&gt;No frame yet.&lt;/p&gt;</source>
        <translation>&lt;p&gt;No frame yet.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="386"/>
        <source>&lt;p&gt;&lt;b&gt;Stage 3, normals&lt;/b&gt;, in view space: each triangle&apos;s normal n = (P2 − P1) × (P3 − P1) / |(P2 − P1) × (P3 − P1)|, and each vertex&apos;s normal the normalised sum of the normals of the triangles around it. A triangle faces away from the camera (at the origin) when n · P1 &amp;gt; 0; the course turns such normals toward the viewer when it shades.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Stage 3, normals&lt;/b&gt;, in view space: each triangle&apos;s normal n = (P2 − P1) × (P3 − P1) / |(P2 − P1) × (P3 − P1)|, and each vertex&apos;s normal the normalised sum of the normals of the triangles around it. A triangle faces away from the camera (at the origin) when n · P1 &amp;gt; 0; the course turns such normals toward the viewer when it shades.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="393"/>
        <source>&lt;p&gt;Skipped for this frame: %1.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Skipped for this frame: %1.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="409"/>
        <source>&lt;p&gt;&lt;b&gt;Triangle %1&lt;/b&gt; (vertices %2, %3, %4):&lt;br&gt;P1 = %5, P2 = %6, P3 = %7&lt;br&gt;(P2 − P1) × (P3 − P1) = %8 × %9</source>
        <translation>&lt;p&gt;&lt;b&gt;Triangle %1&lt;/b&gt; (vertices %2, %3, %4):&lt;br&gt;P1 = %5, P2 = %6, P3 = %7&lt;br&gt;(P2 − P1) × (P3 − P1) = %8 × %9</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="416"/>
        <source> = %1, length %2&lt;br&gt;</source>
        <translation> = %1, length %2&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="421"/>
        <source>n = &lt;b&gt;%1&lt;/b&gt;; n · P1 = %2: %3&lt;/p&gt;</source>
        <translation>n = &lt;b&gt;%1&lt;/b&gt;; n · P1 = %2: %3&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="423"/>
        <source>a back face, drawn in red</source>
        <translation>a back face, drawn in red</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="423"/>
        <source>a front face</source>
        <translation>a front face</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="425"/>
        <source>a degenerate triangle: no normal.&lt;/p&gt;</source>
        <translation>a degenerate triangle: no normal.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="429"/>
        <source>&lt;p&gt;It runs an edge in the same direction as a neighbour does: the two are wound inconsistently (magenta), and one of their normals points the wrong way.&lt;/p&gt;</source>
        <translation>&lt;p&gt;It runs an edge in the same direction as a neighbour does: the two are wound inconsistently (magenta), and one of their normals points the wrong way.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="436"/>
        <source>&lt;p&gt;Vertex normals: N1 = %1 (vertex %2), N2 = %3 (vertex %4), N3 = %5 (vertex %6)&lt;/p&gt;</source>
        <translation>&lt;p&gt;Vertex normals: N1 = %1 (vertex %2), N2 = %3 (vertex %4), N3 = %5 (vertex %6)&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="444"/>
        <source>&lt;p&gt;Pick a pixel (here or in any image) to select its triangle and see its normal worked out.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Pick a pixel (here or in any image) to select its triangle and see its normal worked out.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="454"/>
        <source>&lt;p&gt;&lt;b&gt;Pixel (%1, %2)&lt;/b&gt;: </source>
        <translation>&lt;p&gt;&lt;b&gt;Pixel (%1, %2)&lt;/b&gt;: </translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="456"/>
        <source>no triangle holds it at the cursor (black in the normal map).&lt;/p&gt;</source>
        <translation>no triangle holds it at the cursor (black in the normal map).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="458"/>
        <source>no normal: %1 (grey in the normal map).&lt;/p&gt;</source>
        <translation>no normal: %1 (grey in the normal map).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="461"/>
        <source>the triangle&apos;s normal (flat) %1</source>
        <translation>the triangle&apos;s normal (flat) %1</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="463"/>
        <source>N = α N1 + β N2 + γ N3 with (α, β, γ) = %1: %2, normalised %3</source>
        <translation>N = α N1 + β N2 + γ N3 with (α, β, γ) = %1: %2, normalised %3</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="467"/>
        <source>; V · N &amp;lt; 0, turned toward the viewer: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>; V · N &amp;lt; 0, turned toward the viewer: &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="470"/>
        <source>. Colour (N + 1) / 2 = (%1, %2, %3).&lt;/p&gt;</source>
        <translation>. Colour (N + 1) / 2 = (%1, %2, %3).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="479"/>
        <source>%1 front faces · %2 back faces</source>
        <translation>%1 front faces · %2 back faces</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="495"/>
        <source>x %1, y %2: no triangle</source>
        <translation>x %1, y %2: no triangle</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="499"/>
        <source>x %1, y %2: triangle %3, N = %4, colour (%5, %6, %7)</source>
        <translation>x %1, y %2: triangle %3, N = %4, colour (%5, %6, %7)</translation>
    </message>
</context>
<context>
    <name>rasterlab::PainterView</name>
    <message>
        <location filename="../views/painter_view.cpp" line="73"/>
        <source>Painted</source>
        <translation>Painted</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="75"/>
        <source>Draw</source>
        <translation>Draw</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="77"/>
        <source>Triangle</source>
        <translation>Triangle</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="79"/>
        <source>|b| (distance)</source>
        <translation>|b| (distance)</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="81"/>
        <source>Hidden wrongly</source>
        <translation>Hidden wrongly</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="138"/>
        <source>The triangles in the order the painter paints them: farthest barycentre first. Click a row to select its triangle.</source>
        <translation>The triangles in the order the painter paints them: farthest barycentre first. Click a row to select its triangle.</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="143"/>
        <source>Painter&apos;s image</source>
        <translation>Painter&apos;s image</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="144"/>
        <source>Painted order (first blue, last red)</source>
        <translation>Painted order (first blue, last red)</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="149"/>
        <source>Mark ties on shared edges</source>
        <translation>Mark ties on shared edges</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="152"/>
        <source>Pixels on an edge two triangles share, at the same depth: the z-buffer keeps the first drawn, the painter the last.</source>
        <translation>Pixels on an edge two triangles share, at the same depth: the z-buffer keeps the first drawn, the painter the last.</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="341"/>
        <source>rank of the last triangle painted</source>
        <translation>rank of the last triangle painted</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="342"/>
        <source>painted far to near, no depth test</source>
        <translation>painted far to near, no depth test</translation>
    </message>
    <message numerus="yes">
        <location filename="../views/painter_view.cpp" line="344"/>
        <source>Z-buffer (the same flat colours): %n pixel(s) differ</source>
        <translation>
            <numerusform>Z-buffer (the same flat colours): %n pixel differs</numerusform>
            <numerusform>Z-buffer (the same flat colours): %n pixels differ</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="384"/>
        <source>No frame.</source>
        <translation>No frame.</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="385"/>
        <source>Not worked out yet.</source>
        <translation>Not worked out yet.</translation>
    </message>
    <message numerus="yes">
        <location filename="../views/painter_view.cpp" line="390"/>
        <source>&lt;b&gt;Painter&apos;s algorithm&lt;/b&gt; (seed 004): the %n triangle(s) are sorted by the distance |b| of their barycentre b (view space) to the camera, far to near, each lit once at b, and painted in that order &lt;i&gt;without a depth test&lt;/i&gt;: the last painted stays.</source>
        <translation>
            <numerusform>&lt;b&gt;Painter&apos;s algorithm&lt;/b&gt; (seed 004): the %n triangle is sorted by the distance |b| of its barycentre b (view space) to the camera, far to near, lit once at b, and painted in that order &lt;i&gt;without a depth test&lt;/i&gt;: the last painted stays.</numerusform>
            <numerusform>&lt;b&gt;Painter&apos;s algorithm&lt;/b&gt; (seed 004): the %n triangles are sorted by the distance |b| of their barycentre b (view space) to the camera, far to near, each lit once at b, and painted in that order &lt;i&gt;without a depth test&lt;/i&gt;: the last painted stays.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="395"/>
        <source>The frame shown uses the z-buffer; this view renders the scene again as the painter would.</source>
        <translation>The frame shown uses the z-buffer; this view renders the scene again as the painter would.</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="398"/>
        <source>Against the z-buffer with the same colours, %1 pixels differ: &lt;span style=&apos;color:#d00000&apos;&gt;%2 where a farther triangle was painted after a nearer one&lt;/span&gt; (the order of whole triangles is not the order of their pixels), &lt;span style=&apos;color:#b08800&apos;&gt;%3 on edges two triangles share at the same depth&lt;/span&gt; (the z-buffer keeps the first drawn, the painter the last).</source>
        <translation>Against the z-buffer with the same colours, %1 pixels differ: &lt;span style=&apos;color:#d00000&apos;&gt;%2 where a farther triangle was painted after a nearer one&lt;/span&gt; (the order of whole triangles is not the order of their pixels), &lt;span style=&apos;color:#b08800&apos;&gt;%3 on edges two triangles share at the same depth&lt;/span&gt; (the z-buffer keeps the first drawn, the painter the last).</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="413"/>
        <source>Triangle %1: b = %2, |b| = %3, painted %4 of %5. The z-buffer shows it at %6 pixels; a triangle painted after it covers %7 of them though it is farther there; it covers %8 pixels of nearer triangles painted before it.</source>
        <translation>Triangle %1: b = %2, |b| = %3, painted %4 of %5. The z-buffer shows it at %6 pixels; a triangle painted after it covers %7 of them though it is farther there; it covers %8 pixels of nearer triangles painted before it.</translation>
    </message>
</context>
<context>
    <name>rasterlab::PixelInspector</name>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="199"/>
        <source>%1 = byte 255</source>
        <translation>%1 = byte 255</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="321"/>
        <source>no normal</source>
        <translation>no normal</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="387"/>
        <source>in the plane of N and L</source>
        <translation>in the plane of N and L</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="421"/>
        <source>Step</source>
        <translation>Step</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="421"/>
        <source>Triangle</source>
        <translation>Triangle</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="421"/>
        <source>Depth test</source>
        <translation>Depth test</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="422"/>
        <source>Before</source>
        <translation>Before</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="422"/>
        <source>After</source>
        <translation>After</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="422"/>
        <source>Result</source>
        <translation>Result</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="437"/>
        <source>▶ holds the pixel at the stepping cursor; grey rows are not reached yet. Select a row to see its lighting.</source>
        <translation>▶ holds the pixel at the stepping cursor; grey rows are not reached yet. Select a row to see its lighting.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="127"/>
        <source>Pick a pixel on the image to see its history.</source>
        <translation>Pick a pixel on the image to see its history.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="41"/>
        <source>%1 over %2</source>
        <translation>%1 over %2</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="42"/>
        <source>painted, no depth test</source>
        <translation>painted, no depth test</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="49"/>
        <source>written</source>
        <translation>written</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="57"/>
        <source>rejected: the depth is not a number</source>
        <translation>rejected: the depth is not a number</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="59"/>
        <source>rejected: as far, the earlier keeps it</source>
        <translation>rejected: as far, the earlier keeps it</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="61"/>
        <source>rejected: farther</source>
        <translation>rejected: farther</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="64"/>
        <source>%1 outside [0, 1]</source>
        <translation>%1 outside [0, 1]</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="65"/>
        <source>discarded: depth outside [0, 1]</source>
        <translation>discarded: depth outside [0, 1]</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="86"/>
        <source>cleared to %1</source>
        <translation>cleared to %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="87"/>
        <source>the background</source>
        <translation>the background</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="137"/>
        <source>the final pixel</source>
        <translation>the final pixel</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="145"/>
        <source>Preparing the stepping of this frame: the pixel&apos;s history follows.</source>
        <translation>Preparing the stepping of this frame: the pixel&apos;s history follows.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="185"/>
        <source>The frame could not be traced again: %1</source>
        <translation>The frame could not be traced again: %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="227"/>
        <source>depth %1</source>
        <translation>depth %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="229"/>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="230"/>
        <source>depth %1 (cleared)</source>
        <translation>depth %1 (cleared)</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="249"/>
        <source>Nothing drew here: the pixel keeps the background %1.</source>
        <translation>Nothing drew here: the pixel keeps the background %1.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="258"/>
        <source>The only fragment was rejected: the pixel keeps the background.</source>
        <translation>The only fragment was rejected: the pixel keeps the background.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="259"/>
        <source>Every fragment was rejected (%1): the pixel keeps the background.</source>
        <translation>Every fragment was rejected (%1): the pixel keeps the background.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="263"/>
        <source>Written by triangle %1</source>
        <translation>Written by triangle %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="265"/>
        <source>over 1 earlier write</source>
        <translation>over 1 earlier write</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="267"/>
        <source>over %1 earlier writes</source>
        <translation>over %1 earlier writes</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="269"/>
        <source>1 fragment rejected</source>
        <translation>1 fragment rejected</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="271"/>
        <source>%1 fragments rejected</source>
        <translation>%1 fragments rejected</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="102"/>
        <source>black: the vertex colours mixed here are black</source>
        <translation>black: the vertex colours mixed here are black</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="104"/>
        <source>black: the object colour is black</source>
        <translation>black: the object colour is black</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="105"/>
        <source>black: the light takes away what the ambient term adds</source>
        <translation>black: the light takes away what the ambient term adds</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="106"/>
        <source>black: zero normal and no ambient</source>
        <translation>black: zero normal and no ambient</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="107"/>
        <source>black: no light and no ambient</source>
        <translation>black: no light and no ambient</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="108"/>
        <source>black: the light is at the point and no ambient</source>
        <translation>black: the light is at the point and no ambient</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="109"/>
        <source>black: N.L &lt; 0 and no ambient</source>
        <translation>black: N.L &lt; 0 and no ambient</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="110"/>
        <source>black: the diffuse and specular terms are 0 here and there is no ambient</source>
        <translation>black: the diffuse and specular terms are 0 here and there is no ambient</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="389"/>
        <source>Light %1, directional toward %2 (view), Il = %3</source>
        <translation>Light %1, directional toward %2 (view), Il = %3</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="390"/>
        <source>Light %1 at %2 (view), Il = %3</source>
        <translation>Light %1 at %2 (view), Il = %3</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="393"/>
        <source>  at the point itself (L = 0): nothing</source>
        <translation>  at the point itself (L = 0): nothing</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="398"/>
        <source>att = 1 / (%1 + %2 × %3 + %4 × %3²) = %5</source>
        <translation>att = 1 / (%1 + %2 × %3 + %4 × %3²) = %5</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="402"/>
        <source>d = %1, not attenuated</source>
        <translation>d = %1, not attenuated</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="404"/>
        <source>spot: −L.D = %1 &lt; cos %2° = %3, outside the cone: 0</source>
        <translation>spot: −L.D = %1 &lt; cos %2° = %3, outside the cone: 0</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="407"/>
        <source>spot: −L.D = %1 ≥ cos %2° = %3, %1^%4 = %5</source>
        <translation>spot: −L.D = %1 ≥ cos %2° = %3, %1^%4 = %5</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="415"/>
        <source>  N.L = %1 &lt; 0: behind the surface, nothing</source>
        <translation>  N.L = %1 &lt; 0: behind the surface, nothing</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="417"/>
        <source>  N.L = %1, %2 = %3: diffuse %4, specular %5</source>
        <translation>  N.L = %1, %2 = %3: diffuse %4, specular %5</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="133"/>
        <source>N flipped toward the viewer: V.N &lt; 0, so N := −N before lighting.</source>
        <translation>N flipped toward the viewer: V.N &lt; 0, so N := −N before lighting.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="136"/>
        <source>Zero normal: only degenerate triangles meet here, or the vertex normals cancel out; ambient only.</source>
        <translation>Zero normal: only degenerate triangles meet here, or the vertex normals cancel out; ambient only.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="140"/>
        <source>The light is at the point itself (L = 0): it adds nothing.</source>
        <translation>The light is at the point itself (L = 0): it adds nothing.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="143"/>
        <source>N.L &lt; 0: the light is behind the surface; no diffuse, no specular.</source>
        <translation>N.L &lt; 0: the light is behind the surface; no diffuse, no specular.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="146"/>
        <source>R.V &lt; 0: the reflected ray points away from the viewer; no specular.</source>
        <translation>R.V &lt; 0: the reflected ray points away from the viewer; no specular.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="163"/>
        <source>Outside the cone of light %1: −L.D = %2 is below cos %3° = %4; it adds nothing here.</source>
        <translation>Outside the cone of light %1: −L.D = %2 is below cos %3° = %4; it adds nothing here.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="171"/>
        <source>One-sided lighting: the back of the surface is seen (V.N &lt; 0) and N is not turned toward the viewer.</source>
        <translation>One-sided lighting: the back of the surface is seen (V.N &lt; 0) and N is not turned toward the viewer.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="181"/>
        <source>Texture at (s, t) = (%1, %2): texel %3.</source>
        <translation>Texture at (s, t) = (%1, %2): texel %3.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="186"/>
        <source>Seed 001&apos;s text and its reference images disagree here: the texel nearest to (s w, t h) once the coordinates wrap is %1; the images&apos; (int)(s w + 0.5) mod w gives %2, which these rules follow.</source>
        <translation>Seed 001&apos;s text and its reference images disagree here: the texel nearest to (s w, t h) once the coordinates wrap is %1; the images&apos; (int)(s w + 0.5) mod w gives %2, which these rules follow.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="190"/>
        <source>Seed 001&apos;s text and its reference images disagree here: the texel nearest to (s w, t h) once the coordinates wrap is %1, which these rules follow; the images&apos; (int)(s w + 0.5) mod w gives %2.</source>
        <translation>Seed 001&apos;s text and its reference images disagree here: the texel nearest to (s w, t h) once the coordinates wrap is %1, which these rules follow; the images&apos; (int)(s w + 0.5) mod w gives %2.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="207"/>
        <source>Clamped: %1 above the colour scale %2, written as byte 255.</source>
        <translation>Clamped: %1 above the colour scale %2, written as byte 255.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="216"/>
        <source>%1 (clamped)</source>
        <translation>%1 (clamped)</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="221"/>
        <source>Gouraud shading, the vertices&apos; colours mixed</source>
        <translation>Gouraud shading, the vertices&apos; colours mixed</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="222"/>
        <source>C = α C1 + β C2 + γ C3</source>
        <translation>C = α C1 + β C2 + γ C3</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="238"/>
        <source>not lit, the object colour as it is</source>
        <translation>not lit, the object colour as it is</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="239"/>
        <source>I = O (the object colour)</source>
        <translation>I = O (the object colour)</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="248"/>
        <source>the course&apos;s Phong lighting model</source>
        <translation>the course&apos;s Phong lighting model</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="249"/>
        <source>Lambert with Blinn-Phong highlights (command files)</source>
        <translation>Lambert with Blinn-Phong highlights (command files)</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="251"/>
        <source>Painter&apos;s algorithm: lit as flat shading, once at the triangle&apos;s barycentre; the triangles are painted far to near without a depth test.</source>
        <translation>Painter&apos;s algorithm: lit as flat shading, once at the triangle&apos;s barycentre; the triangles are painted far to near without a depth test.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="256"/>
        <source>Flat shading: evaluated once, at the triangle&apos;s barycentre with the triangle&apos;s normal; every pixel of the triangle gets this colour.</source>
        <translation>Flat shading: evaluated once, at the triangle&apos;s barycentre with the triangle&apos;s normal; every pixel of the triangle gets this colour.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="260"/>
        <source>%1 lights: the diffuse and specular terms are sums over them; the numbers filled in are the first light&apos;s.</source>
        <translation>%1 lights: the diffuse and specular terms are sums over them; the numbers filled in are the first light&apos;s.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="279"/>
        <source>I = Ke + Ia ka + Σ att spot (Il Od kd (N.L) + Il ks (N.H)^n)</source>
        <translation>I = Ke + Ia ka + Σ att spot (Il Od kd (N.L) + Il ks (N.H)^n)</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="280"/>
        <source>I = Ke + Ia ka + Σ att spot (Il Od kd (N.L) + Il ks (R.V)^n)</source>
        <translation>I = Ke + Ia ka + Σ att spot (Il Od kd (N.L) + Il ks (R.V)^n)</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="281"/>
        <source>att = 1 / (kc + kl d + kq d²) for a positional light, 1 for a directional one; spot = (−L.D)^exp inside the cone, 0 outside, 1 for a light that is no spot.</source>
        <translation>att = 1 / (kc + kl d + kq d²) for a positional light, 1 for a directional one; spot = (−L.D)^exp inside the cone, 0 outside, 1 for a light that is no spot.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="286"/>
        <source>I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n</source>
        <translation>I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="293"/>
        <source>I = Σ Il O (N.L) + Il (H.N)^s, over the lights with N.L ≥ 0</source>
        <translation>I = Σ Il O (N.L) + Il (H.N)^s, over the lights with N.L ≥ 0</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="295"/>
        <source>I = Σ Il O (N.L), over the lights with N.L ≥ 0</source>
        <translation>I = Σ Il O (N.L), over the lights with N.L ≥ 0</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="352"/>
        <source>%1 (the other lights)</source>
        <translation>%1 (the other lights)</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="371"/>
        <source>Ia = %1, ka = %2, Il = %3, Od = %4, kd = %5, ks = %6</source>
        <translation>Ia = %1, ka = %2, Il = %3, Od = %4, kd = %5, ks = %6</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="375"/>
        <source>Il = %1, O = %2</source>
        <translation>Il = %1, O = %2</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="378"/>
        <source>Ke = %1: the material&apos;s own light</source>
        <translation>Ke = %1: the material&apos;s own light</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="635"/>
        <source>Your renderer&apos;s colour here: (%1, %2, %3); ours (%4, %5, %6).</source>
        <translation>Your renderer&apos;s colour here: (%1, %2, %3); ours (%4, %5, %6).</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="654"/>
        <source>No triangle of ours holds this pixel.</source>
        <translation>No triangle of ours holds this pixel.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="657"/>
        <source>The terms are worked out for the course&apos;s lighting in flat or Phong shading only.</source>
        <translation>The terms are worked out for the course&apos;s lighting in flat or Phong shading only.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="662"/>
        <source>For your colour, each term alone:</source>
        <translation>For your colour, each term alone:</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="708"/>
        <source>start</source>
        <translation>start</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="714"/>
        <location filename="../views/pixel_inspector.cpp" line="915"/>
        <source>end</source>
        <translation>end</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="722"/>
        <source>holds the pixel at the stepping cursor</source>
        <translation>holds the pixel at the stepping cursor</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="723"/>
        <source>not reached yet by the stepping cursor</source>
        <translation>not reached yet by the stepping cursor</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="738"/>
        <source>not kept</source>
        <translation>not kept</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="739"/>
        <source>Without stepping, the colours of writes overwritten later are not kept.</source>
        <translation>Without stepping, the colours of writes overwritten later are not kept.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="856"/>
        <source>Before: %1</source>
        <translation>Before: %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="896"/>
        <source>Without stepping, only the lighting of the fragment that holds the pixel at the end is recorded.</source>
        <translation>Without stepping, only the lighting of the fragment that holds the pixel at the end is recorded.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="899"/>
        <source>The cleared pixel is not lit.</source>
        <translation>The cleared pixel is not lit.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="902"/>
        <source>No fragment holds the pixel at the cursor: select a row of the history to see its lighting.</source>
        <translation>No fragment holds the pixel at the cursor: select a row of the history to see its lighting.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="914"/>
        <source>Lighting of step %1, triangle %2: %3</source>
        <translation>Lighting of step %1, triangle %2: %3</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="919"/>
        <source>(rejected: this colour was never written)</source>
        <translation>(rejected: this colour was never written)</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="932"/>
        <source>object colour</source>
        <translation>object colour</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="935"/>
        <source>emission</source>
        <translation>emission</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="937"/>
        <source>ambient</source>
        <translation>ambient</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="942"/>
        <source>diffuse %1</source>
        <translation>diffuse %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="945"/>
        <source>specular %1</source>
        <translation>specular %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="949"/>
        <source>diffuse</source>
        <translation>diffuse</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="951"/>
        <source>specular</source>
        <translation>specular</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="978"/>
        <source>No special case: every term applies as written.</source>
        <translation>No special case: every term applies as written.</translation>
    </message>
</context>
<context>
    <name>rasterlab::ProjectionCanvas</name>
    <message>
        <location filename="../views/projection_view.cpp" line="161"/>
        <source>Click a triangle to select it; wheel to zoom, drag to pan, double-click to fit.</source>
        <translation>Click a triangle to select it; wheel to zoom, drag to pan, double-click to fit.</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="389"/>
        <source>No frame yet.</source>
        <translation>No frame yet.</translation>
    </message>
</context>
<context>
    <name>rasterlab::ProjectionSideView</name>
    <message>
        <location filename="../views/projection_view.cpp" line="615"/>
        <source>view z (= w) →</source>
        <translation>view z (= w) →</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="615"/>
        <source>clip w →</source>
        <translation>clip w →</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="619"/>
        <source>y ↑</source>
        <translation>y ↑</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="630"/>
        <source>eye plane w = 0: the plain divide clips nothing</source>
        <translation>eye plane w = 0: the plain divide clips nothing</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="631"/>
        <source>near plane w = %1</source>
        <translation>near plane w = %1</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="634"/>
        <source>the object lies behind the eye (w &lt; 0): N points away from it</source>
        <translation>the object lies behind the eye (w &lt; 0): N points away from it</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="638"/>
        <source>● made by clipping: %1</source>
        <translation>● made by clipping: %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::ProjectionView</name>
    <message>
        <location filename="../views/projection_view.cpp" line="679"/>
        <source>NDC</source>
        <translation>NDC</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="680"/>
        <source>Show the vertices in normalised device coordinates, [-1, 1]</source>
        <translation>Show the vertices in normalised device coordinates, [-1, 1]</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="683"/>
        <source>Pixels</source>
        <translation>Pixels</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="685"/>
        <source>Show the vertices in pixels, snapped as scan conversion receives them</source>
        <translation>Show the vertices in pixels, snapped as scan conversion receives them</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="694"/>
        <source>Fit</source>
        <translation>Fit</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="695"/>
        <source>Show the whole window and its margin</source>
        <translation>Show the whole window and its margin</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="820"/>
        <source>No frame yet.</source>
        <translation>No frame yet.</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="825"/>
        <source>inside %1, clipped %2 (%3 on screen), culled %4, back faces %5; behind %6, clipped away %7</source>
        <translation>inside %1, clipped %2 (%3 on screen), culled %4, back faces %5; behind %6, clipped away %7</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="836"/>
        <source>beyond the guard band %1</source>
        <translation>beyond the guard band %1</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="838"/>
        <source>not finite %1</source>
        <translation>not finite %1</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="839"/>
        <source>%1 inside · %2 clipped · %3 culled · %4 behind</source>
        <translation>%1 inside · %2 clipped · %3 culled · %4 behind</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="845"/>
        <source>%1 drawn whole (inside): %2&lt;br&gt;</source>
        <translation>%1 drawn whole (inside): %2&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="846"/>
        <source>%1 clipped: %2, drawn as %3 fan triangles&lt;br&gt;</source>
        <translation>%1 clipped: %2, drawn as %3 fan triangles&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="850"/>
        <source>%1 culled (clockwise on screen): %2; hidden back faces: %3&lt;br&gt;</source>
        <translation>%1 culled (clockwise on screen): %2; hidden back faces: %3&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="854"/>
        <source>Nothing on screen: behind the near plane %1; outside a clip plane %2</source>
        <translation>Nothing on screen: behind the near plane %1; outside a clip plane %2</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="857"/>
        <source>; beyond the guard band %1</source>
        <translation>; beyond the guard band %1</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="858"/>
        <source>; not finite %1</source>
        <translation>; not finite %1</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="862"/>
        <source>%1 screen triangles go to scan conversion. The plain divide clips nothing (seed 000 as written; seed 001&apos;s HW2): %2 wholly behind the eye, drawn mirrored through the centre; %3 across the eye plane, drawn wrong.</source>
        <translation>%1 screen triangles go to scan conversion. The plain divide clips nothing (seed 000 as written; seed 001&apos;s HW2): %2 wholly behind the eye, drawn mirrored through the centre; %3 across the eye plane, drawn wrong.</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="870"/>
        <source>%1 screen triangles go to scan conversion; the near plane is w = %2.</source>
        <translation>%1 screen triangles go to scan conversion; the near plane is w = %2.</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="875"/>
        <source>%1 selected, %2 being drawn</source>
        <translation>%1 selected, %2 being drawn</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="897"/>
        <source>&lt;p&gt;&lt;b&gt;Projection.&lt;/b&gt; Every vertex goes to clip space, pClip = clipFromView · pView, and is divided by its w without any clipping, as seed 000 writes the formula and seed 001&apos;s HW2 does (&quot;frustum clipping happens here in OpenGL, but we won&apos;t add it&quot;): pNdc = pClip.xy / w. A vertex behind the eye (w &amp;lt; 0) lands mirrored through the centre; a triangle across the eye plane wraps through infinity. Clipping at the near plane (Shading &amp;gt; Projection) draws only what lies in front.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Projection.&lt;/b&gt; Every vertex goes to clip space, pClip = clipFromView · pView, and is divided by its w without any clipping, as seed 000 writes the formula and seed 001&apos;s HW2 does (&quot;frustum clipping happens here in OpenGL, but we won&apos;t add it&quot;): pNdc = pClip.xy / w. A vertex behind the eye (w &amp;lt; 0) lands mirrored through the centre; a triangle across the eye plane wraps through infinity. Clipping at the near plane (Shading &amp;gt; Projection) draws only what lies in front.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="904"/>
        <source>&lt;p&gt;&lt;b&gt;Projection.&lt;/b&gt; Every vertex goes to clip space, pClip = clipFromView · pView. A triangle crossing the near plane w = near is clipped (Sutherland-Hodgman) and its polygon cut into a fan, so nothing is divided by a w at or behind the camera. Then pNdc = pClip.xy / w, and the pixels are x = (x_ndc + 1) W/2, y = (1 − y_ndc) H/2.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Projection.&lt;/b&gt; Every vertex goes to clip space, pClip = clipFromView · pView. A triangle crossing the near plane w = near is clipped (Sutherland-Hodgman) and its polygon cut into a fan, so nothing is divided by a w at or behind the camera. Then pNdc = pClip.xy / w, and the pixels are x = (x_ndc + 1) W/2, y = (1 − y_ndc) H/2.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="911"/>
        <source>&lt;p&gt;For the course camera pClip = ((d/hx) x, (d/hy) y, z, z): x_ndc = (d/hx) x/z, y_ndc = (d/hy) y/z, and the pixel coordinates are truncated.&lt;/p&gt;</source>
        <translation>&lt;p&gt;For the course camera pClip = ((d/hx) x, (d/hy) y, z, z): x_ndc = (d/hx) x/z, y_ndc = (d/hy) y/z, and the pixel coordinates are truncated.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="919"/>
        <source>&lt;p&gt;Click a triangle to see the numbers of its first vertex.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Click a triangle to see the numbers of its first vertex.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="939"/>
        <source>&lt;p&gt;&lt;b&gt;Triangle %1&lt;/b&gt; (mesh triangle %2%3), its first vertex, vertex %4:</source>
        <translation>&lt;p&gt;&lt;b&gt;Triangle %1&lt;/b&gt; (mesh triangle %2%3), its first vertex, vertex %4:</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="942"/>
        <source>, clipped</source>
        <translation>, clipped</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="947"/>
        <source>made by clipping, on the edge from vertex %1 to vertex %2 at t = %3</source>
        <translation>made by clipping, on the edge from vertex %1 to vertex %2 at t = %3</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="972"/>
        <source>not snapped</source>
        <translation>not snapped</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="975"/>
        <source>truncated</source>
        <translation>truncated</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="975"/>
        <source>rounded</source>
        <translation>rounded</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="978"/>
        <source>truncated to 1/%1 pixel</source>
        <translation>truncated to 1/%1 pixel</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="979"/>
        <source>rounded to 1/%1 pixel</source>
        <translation>rounded to 1/%1 pixel</translation>
    </message>
</context>
<context>
    <name>rasterlab::ScanlineView</name>
    <message>
        <location filename="../views/scanline_view.cpp" line="305"/>
        <source>No triangle to show: step into the frame or pick a pixel.</source>
        <translation>No triangle to show: step into the frame or pick a pixel.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="258"/>
        <source>long edge</source>
        <translation>long edge</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="258"/>
        <source>upper edge</source>
        <translation>upper edge</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="259"/>
        <source>lower edge</source>
        <translation>lower edge</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="654"/>
        <source>No frame yet.</source>
        <translation>No frame yet.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="657"/>
        <source>Start of the frame: step forward to walk the first triangle, or pick a pixel to see the triangle holding it.</source>
        <translation>Start of the frame: step forward to walk the first triangle, or pick a pixel to see the triangle holding it.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="660"/>
        <source>Pick a pixel, or step through the frame, to see a triangle scan converted.</source>
        <translation>Pick a pixel, or step through the frame, to see a triangle scan converted.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="665"/>
        <source>&lt;b&gt;Triangle %1&lt;/b&gt; of %2</source>
        <translation>&lt;b&gt;Triangle %1&lt;/b&gt; of %2</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="668"/>
        <source>scanline %1</source>
        <translation>scanline %1</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="670"/>
        <source>pixel %1</source>
        <translation>pixel %1</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="673"/>
        <source>at the stepping cursor</source>
        <translation>at the stepping cursor</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="674"/>
        <source>the triangle selected (the cursor is at the %1 of the frame)</source>
        <translation>the triangle selected (the cursor is at the %1 of the frame)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="675"/>
        <source>start</source>
        <translation>start</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="676"/>
        <source>end</source>
        <translation>end</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="704"/>
        <source>Vertices sorted by y: top %1, middle %2, bottom %3. The long edge runs from the top to the bottom; the two short edges meet at the middle vertex.</source>
        <translation>Vertices sorted by y: top %1, middle %2, bottom %3. The long edge runs from the top to the bottom; the two short edges meet at the middle vertex.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="709"/>
        <source>Its area on the screen is zero: it has no inside and is not scanned.</source>
        <translation>Its area on the screen is zero: it has no inside and is not scanned.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="714"/>
        <source>(s1 &amp;minus; s0) &amp;times; (s2 &amp;minus; s0) = %1, so the middle vertex is %2 of the long edge: the long edge bounds the spans on the %3.</source>
        <translation>(s1 &amp;minus; s0) &amp;times; (s2 &amp;minus; s0) = %1, so the middle vertex is %2 of the long edge: the long edge bounds the spans on the %3.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="717"/>
        <location filename="../views/scanline_view.cpp" line="718"/>
        <location filename="../views/scanline_view.cpp" line="778"/>
        <source>right</source>
        <translation>right</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="717"/>
        <location filename="../views/scanline_view.cpp" line="718"/>
        <location filename="../views/scanline_view.cpp" line="778"/>
        <source>left</source>
        <translation>left</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="692"/>
        <source>long</source>
        <translation>long</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="692"/>
        <source>upper</source>
        <translation>upper</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="692"/>
        <source>lower</source>
        <translation>lower</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="765"/>
        <source>from</source>
        <translation>from</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="766"/>
        <source>to</source>
        <translation>to</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="767"/>
        <source>x on its first row</source>
        <translation>x on its first row</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="770"/>
        <source>dx/dy</source>
        <translation>dx/dy</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="771"/>
        <source>horizontal</source>
        <translation>horizontal</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="773"/>
        <source>rows</source>
        <translation>rows</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="775"/>
        <location filename="../views/scanline_view.cpp" line="829"/>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="778"/>
        <source>side</source>
        <translation>side</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="782"/>
        <source>Only rows %1 to %2 are on the screen: the walk starts and stops there.</source>
        <translation>Only rows %1 to %2 are on the screen: the walk starts and stops there.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="724"/>
        <source>No row of this triangle is on the screen.</source>
        <translation>No row of this triangle is on the screen.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="267"/>
        <source>your span</source>
        <translation>your span</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="268"/>
        <source>only yours</source>
        <translation>only yours</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="269"/>
        <source>only ours</source>
        <translation>only ours</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="738"/>
        <source>Here the additions are seed 001&apos;s DDA, in double: an edge that lands a hair below a row in double leaves that row to the triangle above, where an exact walk would find the edge through the row&apos;s samples.</source>
        <translation>Here the additions are seed 001&apos;s DDA, in double: an edge that lands a hair below a row in double leaves that row to the triangle above, where an exact walk would find the edge through the row&apos;s samples.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="829"/>
        <source>%1 to %2</source>
        <translation>%1 to %2</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="833"/>
        <source>Your renderer: no pixel on this row (ours: %1).</source>
        <translation>Your renderer: no pixel on this row (ours: %1).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="838"/>
        <source>Your renderer: pixels %1 to %2 (ours: %3).</source>
        <translation>Your renderer: pixels %1 to %2 (ours: %3).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="859"/>
        <source>%1(%2) = %3, where the %4 edge crosses its first row</source>
        <translation>%1(%2) = %3, where the %4 edge crosses its first row</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="865"/>
        <source>%1(%2) = %3, where the %4 edge crosses the first row on the screen</source>
        <translation>%1(%2) = %3, where the %4 edge crosses the first row on the screen</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="873"/>
        <source>%1(%2) = %1(%3) + dx/dy = %4 + %5 = %6 along the %7 edge</source>
        <translation>%1(%2) = %1(%3) + dx/dy = %4 + %5 = %6 along the %7 edge</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="888"/>
        <source>Scanline y = %1</source>
        <translation>Scanline y = %1</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="890"/>
        <source>(sampled at y = %1)</source>
        <translation>(sampled at y = %1)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="902"/>
        <source>Seed 001&apos;s DDA: x_left and x_right are sums in double, one addition of dx/dy a row, the rounding of each carried along (no snapping). Pixels x = ceil(x_left) = %1 while x &amp;lt; x_right: up to ceil(x_right) &amp;minus; 1 = %2 (a sample exactly on the right edge belongs to the next triangle).</source>
        <translation>Seed 001&apos;s DDA: x_left and x_right are sums in double, one addition of dx/dy a row, the rounding of each carried along (no snapping). Pixels x = ceil(x_left) = %1 while x &amp;lt; x_right: up to ceil(x_right) &amp;minus; 1 = %2 (a sample exactly on the right edge belongs to the next triangle).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="909"/>
        <source>Top-left rule: the samples with x_left &amp;le; x%1 &amp;lt; x_right, pixels ceil(x_left%2) = %3 to ceil(x_right%2) &amp;minus; 1 = %4 (a sample exactly on the right edge belongs to the next triangle).</source>
        <translation>Top-left rule: the samples with x_left &amp;le; x%1 &amp;lt; x_right, pixels ceil(x_left%2) = %3 to ceil(x_right%2) &amp;minus; 1 = %4 (a sample exactly on the right edge belongs to the next triangle).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="916"/>
        <source>Inclusive rule: the pixels from ceil(x_left%1) = %2 to floor(x_right%1) = %3, both ends included (a sample exactly on an edge is inside).</source>
        <translation>Inclusive rule: the pixels from ceil(x_left%1) = %2 to floor(x_right%1) = %3, both ends included (a sample exactly on an edge is inside).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="924"/>
        <source>No pixel on this row</source>
        <translation>No pixel on this row</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="925"/>
        <source>the edges cross it between two samples.</source>
        <translation>the edges cross it between two samples.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="926"/>
        <source>they are all off the screen.</source>
        <translation>they are all off the screen.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="929"/>
        <source>Span [%1, %2): 1 pixel.</source>
        <translation>Span [%1, %2): 1 pixel.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="930"/>
        <source>Span [%1, %2): %3 pixels.</source>
        <translation>Span [%1, %2): %3 pixels.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="933"/>
        <source>(cut to the screen&apos;s columns 0 to %1)</source>
        <translation>(cut to the screen&apos;s columns 0 to %1)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="936"/>
        <source>The pixel at the cursor is x = %1.</source>
        <translation>The pixel at the cursor is x = %1.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="984"/>
        <source>At the ends of the span, the barycentrics (&amp;alpha;, &amp;beta;, &amp;gamma;) of the sample with respect to the screen triangle P1 %1, P2 %2, P3 %3 give the depth, from the vertices&apos; z1 = %4, z2 = %5, z3 = %6:</source>
        <translation>At the ends of the span, the barycentrics (&amp;alpha;, &amp;beta;, &amp;gamma;) of the sample with respect to the screen triangle P1 %1, P2 %2, P3 %3 give the depth, from the vertices&apos; z1 = %4, z2 = %5, z3 = %6:</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="989"/>
        <source>1/z = 1/z1 + &amp;beta; (1/z2 &amp;minus; 1/z1) + &amp;gamma; (1/z3 &amp;minus; 1/z1) (perspective-correct: 1/z is linear on the screen)</source>
        <translation>1/z = 1/z1 + &amp;beta; (1/z2 &amp;minus; 1/z1) + &amp;gamma; (1/z3 &amp;minus; 1/z1) (perspective-correct: 1/z is linear on the screen)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="991"/>
        <source>z = z1 + &amp;beta; (z2 &amp;minus; z1) + &amp;gamma; (z3 &amp;minus; z1)</source>
        <translation>z = z1 + &amp;beta; (z2 &amp;minus; z1) + &amp;gamma; (z3 &amp;minus; z1)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="954"/>
        <source>depth</source>
        <translation>depth</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="954"/>
        <source>normal</source>
        <translation>normal</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="957"/>
        <source>not computed (nothing is lit)</source>
        <translation>not computed (nothing is lit)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="958"/>
        <source>zero</source>
        <translation>zero</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1007"/>
        <source>Pixel (x, y) is sampled at the point (x, y) itself.</source>
        <translation>Pixel (x, y) is sampled at the point (x, y) itself.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1008"/>
        <source>Pixel (x, y) is sampled at (x + %1, y + %1).</source>
        <translation>Pixel (x, y) is sampled at (x + %1, y + %1).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1011"/>
        <source>The normal is N1 + &amp;beta; (N2 &amp;minus; N1) + &amp;gamma; (N3 &amp;minus; N1) from the vertex normals, normalised%1.</source>
        <translation>The normal is N1 + &amp;beta; (N2 &amp;minus; N1) + &amp;gamma; (N3 &amp;minus; N1) from the vertex normals, normalised%1.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1014"/>
        <source>, with the barycentrics weighted by 1/w (perspective-correct)</source>
        <translation>, with the barycentrics weighted by 1/w (perspective-correct)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1038"/>
        <source>Seed 001&apos;s DDA steps the depth and the weights (&amp;beta;, &amp;gamma;) of P2 and P3 as it steps x: down each edge by the edge&apos;s own increment a row, then along the row from their values at x_left by (value at x_right &amp;minus; value at x_left) / (x_right &amp;minus; x_left), one addition a pixel, in double. Every attribute (colour, normal, texture coordinates) is mixed with these weights.</source>
        <translation>Seed 001&apos;s DDA steps the depth and the weights (&amp;beta;, &amp;gamma;) of P2 and P3 as it steps x: down each edge by the edge&apos;s own increment a row, then along the row from their values at x_left by (value at x_right &amp;minus; value at x_left) / (x_right &amp;minus; x_left), one addition a pixel, in double. Every attribute (colour, normal, texture coordinates) is mixed with these weights.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1044"/>
        <source>On this row %1 = %2 at x_left and %3 at x_right: %1 + %4 a pixel; &amp;beta; + %5 and &amp;gamma; + %6 a pixel.</source>
        <translation>On this row %1 = %2 at x_left and %3 at x_right: %1 + %4 a pixel; &amp;beta; + %5 and &amp;gamma; + %6 a pixel.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1049"/>
        <source>(%1, %2): %3 = %4 + (%1 &amp;minus; %5) &amp;times; %6 = %7.</source>
        <translation>(%1, %2): %3 = %4 + (%1 &amp;minus; %5) &amp;times; %6 = %7.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1058"/>
        <source>(%1, %2): %3 after %4 additions of %5 = %6.</source>
        <translation>(%1, %2): %3 after %4 additions of %5 = %6.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="732"/>
        <source>Edge walking: from one scanline to the next, each edge&apos;s x changes by its constant dx/dy, one addition per edge and row: x_left(y+1) = x_left(y) + dx/dy. The span between the two crossings is filled; the long edge bounds every row, the upper edge the rows above the middle vertex, the lower edge the rest.</source>
        <translation>Edge walking: from one scanline to the next, each edge&apos;s x changes by its constant dx/dy, one addition per edge and row: x_left(y+1) = x_left(y) + dx/dy. The span between the two crossings is filled; the long edge bounds every row, the upper edge the rows above the middle vertex, the lower edge the rest.</translation>
    </message>
</context>
<context>
    <name>rasterlab::StageStrip</name>
    <message>
        <location filename="../views/stage_strip.cpp" line="58"/>
        <source>Camera basis</source>
        <translation>Camera basis</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="60"/>
        <source>View coordinates</source>
        <translation>View coordinates</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="62"/>
        <source>Normals</source>
        <translation>Normals</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="64"/>
        <source>Projection</source>
        <translation>Projection</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="66"/>
        <source>Scan conversion</source>
        <translation>Scan conversion</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="68"/>
        <source>Z-buffer</source>
        <translation>Z-buffer</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="70"/>
        <source>Lighting</source>
        <translation>Lighting</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="78"/>
        <source>Camera</source>
        <translation>Camera</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="80"/>
        <source>View</source>
        <translation>View</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="82"/>
        <source>Scan</source>
        <translation>Scan</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="92"/>
        <source>no course camera: each draw brings its own view matrix</source>
        <translation>no course camera: each draw brings its own view matrix</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="96"/>
        <source>nothing is lit: no light reads a normal</source>
        <translation>nothing is lit: no light reads a normal</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="104"/>
        <source>nothing is lit: each pixel takes its object&apos;s own colour</source>
        <translation>nothing is lit: each pixel takes its object&apos;s own colour</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="117"/>
        <source>near clip</source>
        <translation>near clip</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="119"/>
        <source>plain divide</source>
        <translation>plain divide</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="121"/>
        <source>same side</source>
        <translation>same side</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="130"/>
        <source>triangles are clipped at the near plane before the divide, so nothing at or behind the eye is divided by its w (the course and GPU-like rules)</source>
        <translation>triangles are clipped at the near plane before the divide, so nothing at or behind the eye is divided by its w (the course and GPU-like rules)</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="134"/>
        <source>every vertex is divided by its w without clipping, as seed 000 writes it and seed 001&apos;s HW2 does (&quot;we won&apos;t add it&quot;): a triangle behind the eye lands mirrored through the centre, one across the eye plane wraps through infinity</source>
        <translation>every vertex is divided by its w without clipping, as seed 000 writes it and seed 001&apos;s HW2 does (&quot;we won&apos;t add it&quot;): a triangle behind the eye lands mirrored through the centre, one across the eye plane wraps through infinity</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="140"/>
        <source>triangles wholly in front of or wholly behind the eye are divided as they are; those across the eye plane are clipped at the near plane</source>
        <translation>triangles wholly in front of or wholly behind the eye are divided as they are; those across the eye plane are clipped at the near plane</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="158"/>
        <source>(skipped)</source>
        <translation>(skipped)</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="166"/>
        <source>%1 is skipped: %2</source>
        <translation>%1 is skipped: %2</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="168"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="173"/>
        <source>Your renderer&apos;s stage passed the check.</source>
        <translation>Your renderer&apos;s stage passed the check.</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="174"/>
        <source>Your renderer&apos;s stage departs from the lecture&apos;s: see the Check dock.</source>
        <translation>Your renderer&apos;s stage departs from the lecture&apos;s: see the Check dock.</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="236"/>
        <source>while stepping, stages 5-7 run together, fragment by fragment</source>
        <translation>while stepping, stages 5-7 run together, fragment by fragment</translation>
    </message>
</context>
<context>
    <name>rasterlab::SteppingBar</name>
    <message>
        <location filename="../views/stepping_bar.cpp" line="75"/>
        <source>Stage</source>
        <translation>Stage</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="77"/>
        <source>Triangle</source>
        <translation>Triangle</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="79"/>
        <source>Scanline</source>
        <translation>Scanline</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="81"/>
        <source>Span</source>
        <translation>Span</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="83"/>
        <source>Pixel</source>
        <translation>Pixel</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="103"/>
        <source>Jump to &amp;Start</source>
        <translation>Jump to &amp;Start</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="104"/>
        <source>Step &amp;Back</source>
        <translation>Step &amp;Back</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="107"/>
        <source>&amp;Play / Pause</source>
        <translation>&amp;Play / Pause</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="110"/>
        <source>Step &amp;Forward</source>
        <translation>Step &amp;Forward</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="112"/>
        <source>Jump to &amp;End</source>
        <translation>Jump to &amp;End</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="114"/>
        <source>&amp;Continue to Breakpoint</source>
        <translation>&amp;Continue to Breakpoint</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="140"/>
        <source>Step by</source>
        <translation>Step by</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="171"/>
        <source> steps/s</source>
        <translation> steps/s</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="172"/>
        <source>How many steps a second Play makes</source>
        <translation>How many steps a second Play makes</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="178"/>
        <source>The frame, fragment by fragment: drag to scrub</source>
        <translation>The frame, fragment by fragment: drag to scrub</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="262"/>
        <source>stepping is being prepared</source>
        <translation>stepping is being prepared</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="263"/>
        <source>no stepping: %1</source>
        <translation>no stepping: %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::TrapezoidView</name>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="102"/>
        <source>No triangle to show: step into the frame or pick a pixel.</source>
        <translation>No triangle to show: step into the frame or pick a pixel.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="255"/>
        <source>upper trapezoid</source>
        <translation>upper trapezoid</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="256"/>
        <source>lower trapezoid</source>
        <translation>lower trapezoid</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="267"/>
        <source>scanline j</source>
        <translation>scanline j</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="317"/>
        <source>No frame yet.</source>
        <translation>No frame yet.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="319"/>
        <source>Pick a pixel, or step through the frame, to see a triangle split into trapezoids.</source>
        <translation>Pick a pixel, or step through the frame, to see a triangle split into trapezoids.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="325"/>
        <source>&lt;b&gt;Triangle %1&lt;/b&gt; of %2</source>
        <translation>&lt;b&gt;Triangle %1&lt;/b&gt; of %2</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="326"/>
        <source>scanline %1</source>
        <translation>scanline %1</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="327"/>
        <source>pixel %1</source>
        <translation>pixel %1</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="329"/>
        <source>at the stepping cursor</source>
        <translation>at the stepping cursor</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="329"/>
        <source>the triangle selected</source>
        <translation>the triangle selected</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="352"/>
        <source>Its area on the screen is zero: it has no inside, no trapezoid, and is not scanned.</source>
        <translation>Its area on the screen is zero: it has no inside, no trapezoid, and is not scanned.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="360"/>
        <source>Vertices sorted by j: top %1, middle %2, bottom %3. The triangle is split at the middle vertex&apos;s row j = %4.</source>
        <translation>Vertices sorted by j: top %1, middle %2, bottom %3. The triangle is split at the middle vertex&apos;s row j = %4.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="365"/>
        <source>The long edge from top to bottom meets that row at s = (%1 &amp;minus; %2) / (%3 &amp;minus; %2) = %4: M&apos; = lerp(s, top, bottom) = %5, %6.</source>
        <translation>The long edge from top to bottom meets that row at s = (%1 &amp;minus; %2) / (%3 &amp;minus; %2) = %4: M&apos; = lerp(s, top, bottom) = %5, %6.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="371"/>
        <source>Two vertices share a row: the triangle is one trapezoid, two of whose corners are the same vertex.</source>
        <translation>Two vertices share a row: the triangle is one trapezoid, two of whose corners are the same vertex.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="376"/>
        <source>Each corner carries the colour Gouraud shading worked out at its vertex, and the depth.</source>
        <translation>Each corner carries the colour Gouraud shading worked out at its vertex, and the depth.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="382"/>
        <source>Each corner carries the depth%1 (colours are carried under Gouraud shading, for a triangle with a pixel on the screen, once the frame&apos;s replay is built).</source>
        <translation>Each corner carries the depth%1 (colours are carried under Gouraud shading, for a triangle with a pixel on the screen, once the frame&apos;s replay is built).</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="384"/>
        <source> as 1/z, which is linear on the screen</source>
        <translation> as 1/z, which is linear on the screen</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="389"/>
        <source>corner</source>
        <translation>corner</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="392"/>
        <source>rows</source>
        <translation>rows</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="400"/>
        <location filename="../views/trapezoid_view.cpp" line="429"/>
        <source>upper</source>
        <translation>upper</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="400"/>
        <location filename="../views/trapezoid_view.cpp" line="429"/>
        <source>lower</source>
        <translation>lower</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="414"/>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="427"/>
        <source>Scanline j = %1, in the %2 trapezoid</source>
        <translation>Scanline j = %1, in the %2 trapezoid</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="442"/>
        <source>No pixel of this row lies between L and R on the screen.</source>
        <translation>No pixel of this row lies between L and R on the screen.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="445"/>
        <source>Pixels i with L_i &amp;le; i%1 &amp;lt; R_i: %2 to %3.</source>
        <translation>Pixels i with L_i &amp;le; i%1 &amp;lt; R_i: %2 to %3.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="450"/>
        <source>Pixels i from ceil(L_i%1) to floor(R_i%1): %2 to %3.</source>
        <translation>Pixels i from ceil(L_i%1) to floor(R_i%1): %2 to %3.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="461"/>
        <source>Pixel i = %1</source>
        <translation>Pixel i = %1</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="471"/>
        <source>The depth test&apos;s z there: %1 (stepped by seed 001&apos;s DDA in double, then rounded to float).</source>
        <translation>The depth test&apos;s z there: %1 (stepped by seed 001&apos;s DDA in double, then rounded to float).</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="475"/>
        <source>z = 1 / (1/z) = %1; the depth test&apos;s z there: %2 (from the barycentrics, in float).</source>
        <translation>z = 1 / (1/z) = %1; the depth test&apos;s z there: %2 (from the barycentrics, in float).</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="478"/>
        <source>The depth test&apos;s z there: %1 (from the barycentrics, in float).</source>
        <translation>The depth test&apos;s z there: %1 (from the barycentrics, in float).</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="486"/>
        <source>The row through the middle vertex belongs to the lower trapezoid only, so no row is scanned twice.</source>
        <translation>The row through the middle vertex belongs to the lower trapezoid only, so no row is scanned twice.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="490"/>
        <source>Pixel (i, j) is sampled at (i + %1, j + %1): t_j and t_i use those.</source>
        <translation>Pixel (i, j) is sampled at (i + %1, j + %1): t_j and t_i use those.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="492"/>
        <source>Top-left rule: a sample exactly on the bottom vertex&apos;s row or on R belongs to the next triangle.</source>
        <translation>Top-left rule: a sample exactly on the bottom vertex&apos;s row or on R belongs to the next triangle.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="494"/>
        <source>Inclusive rule: samples exactly on L, R or the bottom row are inside.</source>
        <translation>Inclusive rule: samples exactly on L, R or the bottom row are inside.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="497"/>
        <source>These rules interpolate colours perspective-correctly (weights over w): the lerps of the seed, linear on the screen, are what the course rules do; the rows and pixels are the same either way.</source>
        <translation>These rules interpolate colours perspective-correctly (weights over w): the lerps of the seed, linear on the screen, are what the course rules do; the rows and pixels are the same either way.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="502"/>
        <source>The same rows and pixels as the edge walk (scan conversion view): L_i and R_i are where the scanline crosses the triangle&apos;s edges.</source>
        <translation>The same rows and pixels as the edge walk (scan conversion view): L_i and R_i are where the scanline crosses the triangle&apos;s edges.</translation>
    </message>
</context>
<context>
    <name>rasterlab::VertexTableModel</name>
    <message>
        <location filename="../views/vertex_table.cpp" line="143"/>
        <source>%1 made by clipping (edge %2-%3, t = %4)</source>
        <translation>%1 made by clipping (edge %2-%3, t = %4)</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="150"/>
        <source>pView = pView(%1) + t (pView(%2) - pView(%1)), on the plane that cut the edge</source>
        <translation>pView = pView(%1) + t (pView(%2) - pView(%1)), on the plane that cut the edge</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="163"/>
        <source>At or behind the near plane: not projected; the triangles through it are clipped</source>
        <translation>At or behind the near plane: not projected; the triangles through it are clipped</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="166"/>
        <location filename="../views/vertex_table.cpp" line="170"/>
        <source>behind</source>
        <translation>behind</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="172"/>
        <source>Exact: %1</source>
        <translation>Exact: %1</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="183"/>
        <source>Mixed along the edge it was made on, as shading does (normalised per pixel)</source>
        <translation>Mixed along the edge it was made on, as shading does (normalised per pixel)</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="206"/>
        <source>Draw</source>
        <translation>Draw</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="208"/>
        <source>Vertex</source>
        <translation>Vertex</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="210"/>
        <source>World (x, y, z)</source>
        <translation>World (x, y, z)</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="212"/>
        <source>View pView</source>
        <translation>View pView</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="214"/>
        <source>NDC pNdc</source>
        <translation>NDC pNdc</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="216"/>
        <source>Screen pScreen</source>
        <translation>Screen pScreen</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="218"/>
        <source>Normal nView</source>
        <translation>Normal nView</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="226"/>
        <source>The draw (object) the vertex belongs to</source>
        <translation>The draw (object) the vertex belongs to</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="228"/>
        <source>The vertex number as in the file (1-based); vertices made by clipping come after the draw&apos;s own</source>
        <translation>The vertex number as in the file (1-based); vertices made by clipping come after the draw&apos;s own</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="232"/>
        <source>P = worldFromModel · P_model</source>
        <translation>P = worldFromModel · P_model</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="234"/>
        <source>pView = [U; V; N](P − C) for the course camera, or the draw&apos;s view matrix times P_model</source>
        <translation>pView = [U; V; N](P − C) for the course camera, or the draw&apos;s view matrix times P_model</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="238"/>
        <source>pNdc = ((d/hx) x/z, (d/hy) y/z) for the course camera, or pClip.xy / pClip.w with pClip = clipFromView · pView</source>
        <translation>pNdc = ((d/hx) x/z, (d/hy) y/z) for the course camera, or pClip.xy / pClip.w with pClip = clipFromView · pView</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="242"/>
        <source>pScreen = ((x_ndc + 1) w/2, (1 − y_ndc) h/2), truncated (snapped to the rules&apos; grid); the tooltip holds the exact value</source>
        <translation>pScreen = ((x_ndc + 1) w/2, (1 − y_ndc) h/2), truncated (snapped to the rules&apos; grid); the tooltip holds the exact value</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="246"/>
        <source>The view-space vertex normal: the normalised sum of the normals of the triangles around it (stage 3)</source>
        <translation>The view-space vertex normal: the normalised sum of the normals of the triangles around it (stage 3)</translation>
    </message>
</context>
<context>
    <name>rasterlab::VertexTableView</name>
    <message>
        <location filename="../views/vertex_table.cpp" line="281"/>
        <source>Only the selected triangle&apos;s vertices</source>
        <translation>Only the selected triangle&apos;s vertices</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="348"/>
        <source>%1 vertices, %2 of them made by clipping</source>
        <translation>%1 vertices, %2 of them made by clipping</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="349"/>
        <source>%1 vertices</source>
        <translation>%1 vertices</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="478"/>
        <source>&lt;p&gt;Select a row, or pick a pixel in the image: its triangle&apos;s three vertices are selected. The numbers of the selected vertex are worked through each formula here.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Select a row, or pick a pixel in the image: its triangle&apos;s three vertices are selected. The numbers of the selected vertex are worked through each formula here.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="481"/>
        <source>&lt;p&gt;No frame yet.&lt;/p&gt;</source>
        <translation>&lt;p&gt;No frame yet.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="505"/>
        <source>Vertex %1 of draw %2 (%3)</source>
        <translation>Vertex %1 of draw %2 (%3)</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="506"/>
        <source>Vertex %1 of %2</source>
        <translation>Vertex %1 of %2</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="513"/>
        <source>&lt;p&gt;Made by clipping the edge %1-%2 where it crosses a plane (the near plane or a clip plane), at t = %3:&lt;br&gt;pView = pView&lt;sub&gt;%1&lt;/sub&gt; + t (pView&lt;sub&gt;%2&lt;/sub&gt; − pView&lt;sub&gt;%1&lt;/sub&gt;) = %4 + %3 (%5 − %4) = &lt;b&gt;%6&lt;/b&gt;&lt;br&gt;World: P = %7 (the same interpolation).&lt;/p&gt;</source>
        <translation>&lt;p&gt;Made by clipping the edge %1-%2 where it crosses a plane (the near plane or a clip plane), at t = %3:&lt;br&gt;pView = pView&lt;sub&gt;%1&lt;/sub&gt; + t (pView&lt;sub&gt;%2&lt;/sub&gt; − pView&lt;sub&gt;%1&lt;/sub&gt;) = %4 + %3 (%5 − %4) = &lt;b&gt;%6&lt;/b&gt;&lt;br&gt;World: P = %7 (the same interpolation).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="524"/>
        <source>&lt;p&gt;World: P = M(t) · worldFromModel · %1 = &lt;b&gt;%2&lt;/b&gt; (M: the animation matrix at t = %3 s)&lt;/p&gt;</source>
        <translation>&lt;p&gt;World: P = M(t) · worldFromModel · %1 = &lt;b&gt;%2&lt;/b&gt; (M: the animation matrix at t = %3 s)&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="529"/>
        <source>&lt;p&gt;World: P = P&lt;sub&gt;model&lt;/sub&gt; = &lt;b&gt;%1&lt;/b&gt; (worldFromModel is the identity)&lt;/p&gt;</source>
        <translation>&lt;p&gt;World: P = P&lt;sub&gt;model&lt;/sub&gt; = &lt;b&gt;%1&lt;/b&gt; (worldFromModel is the identity)&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="533"/>
        <source>&lt;p&gt;World: P = worldFromModel · %1 = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;World: P = worldFromModel · %1 = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="539"/>
        <source>&lt;p&gt;View: pView = [U; V; N](P − C), with C = %1:&lt;br&gt;P − C = %2&lt;br&gt;x = U · (P − C) = %3 · %2 = %4&lt;br&gt;y = V · (P − C) = %5 · %2 = %6&lt;br&gt;z = N · (P − C) = %7 · %2 = %8&lt;br&gt;pView = &lt;b&gt;%9&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;View: pView = [U; V; N](P − C), with C = %1:&lt;br&gt;P − C = %2&lt;br&gt;x = U · (P − C) = %3 · %2 = %4&lt;br&gt;y = V · (P − C) = %5 · %2 = %6&lt;br&gt;z = N · (P − C) = %7 · %2 = %8&lt;br&gt;pView = &lt;b&gt;%9&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="547"/>
        <source>&lt;p&gt;View: pView = viewFromModel · P&lt;sub&gt;model&lt;/sub&gt; (the draw&apos;s own view matrix) = &lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;View: pView = viewFromModel · P&lt;sub&gt;model&lt;/sub&gt; (the draw&apos;s own view matrix) = &lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="555"/>
        <source>&lt;p&gt;z = %1 is not beyond the near plane (w = %2): the vertex is behind, not projected; the triangles through it are clipped there.&lt;/p&gt;</source>
        <translation>&lt;p&gt;z = %1 is not beyond the near plane (w = %2): the vertex is behind, not projected; the triangles through it are clipped there.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="563"/>
        <source>&lt;p&gt;NDC: pNdc = ((d/hx) x/z, (d/hy) y/z) = ((%1/%2) · %3/%4, (%1/%5) · %6/%4) = &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;NDC: pNdc = ((d/hx) x/z, (d/hy) y/z) = ((%1/%2) · %3/%4, (%1/%5) · %6/%4) = &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="568"/>
        <source>&lt;p&gt;Clip: pClip = clipFromView · pView = %1&lt;br&gt;NDC: pNdc = pClip.xy / pClip.w = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Clip: pClip = clipFromView · pView = %1&lt;br&gt;NDC: pNdc = pClip.xy / pClip.w = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="577"/>
        <source>not snapped</source>
        <translation>not snapped</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="579"/>
        <source>truncated, as C&apos;s (int) does</source>
        <translation>truncated, as C&apos;s (int) does</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="581"/>
        <source>truncated to a grid of 1/%1 pixel</source>
        <translation>truncated to a grid of 1/%1 pixel</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="583"/>
        <source>rounded to the nearest 1/%1 pixel</source>
        <translation>rounded to the nearest 1/%1 pixel</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="584"/>
        <source>(1 − y&lt;sub&gt;ndc&lt;/sub&gt;) h/2</source>
        <translation>(1 − y&lt;sub&gt;ndc&lt;/sub&gt;) h/2</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="585"/>
        <source>(y&lt;sub&gt;ndc&lt;/sub&gt; + 1) h/2</source>
        <translation>(y&lt;sub&gt;ndc&lt;/sub&gt; + 1) h/2</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="591"/>
        <source>&lt;p&gt;Screen: pScreen = (x&lt;sub&gt;ndc&lt;/sub&gt; w/2 + w/2, y&lt;sub&gt;ndc&lt;/sub&gt; h/2 + h/2) = (%1 · %2 + %2, %3 · %4 + %4) = %5, %6: &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Screen: pScreen = (x&lt;sub&gt;ndc&lt;/sub&gt; w/2 + w/2, y&lt;sub&gt;ndc&lt;/sub&gt; h/2 + h/2) = (%1 · %2 + %2, %3 · %4 + %4) = %5, %6: &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="597"/>
        <source>&lt;p&gt;Screen: pScreen = ((x&lt;sub&gt;ndc&lt;/sub&gt; + 1) w/2, %1) = ((%2 + 1) · %3, %4) = %5, %6: &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Screen: pScreen = ((x&lt;sub&gt;ndc&lt;/sub&gt; + 1) w/2, %1) = ((%2 + 1) · %3, %4) = %5, %6: &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="606"/>
        <source>&lt;p&gt;Normal: mixed along the edge like pView, %1; shading normalises it per pixel.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normal: mixed along the edge like pView, %1; shading normalises it per pixel.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="610"/>
        <source>&lt;p&gt;Normal: the file&apos;s normal carried to view space by the inverse transpose of viewFromModel: nView = &lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normal: the file&apos;s normal carried to view space by the inverse transpose of viewFromModel: nView = &lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="617"/>
        <source>&lt;p&gt;Normal: the normalised sum of the normals of the %1 triangles around it: nView = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normal: the normalised sum of the normals of the %1 triangles around it: nView = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="623"/>
        <source>&lt;p&gt;Normal: none, %1.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normal: none, %1.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>rasterlab::ZBufferView</name>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="165"/>
        <source>Automatic range (nearest to farthest drawn)</source>
        <translation>Automatic range (nearest to farthest drawn)</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="182"/>
        <source>Grey</source>
        <translation>Grey</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="183"/>
        <source>False colour</source>
        <translation>False colour</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="195"/>
        <source>Nearest (white / red):</source>
        <translation>Nearest (white / red):</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="196"/>
        <source>Farthest (dark / blue):</source>
        <translation>Farthest (dark / blue):</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="197"/>
        <source>Colours:</source>
        <translation>Colours:</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="326"/>
        <source>+&amp;infin;</source>
        <translation>+&amp;infin;</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="328"/>
        <source>stored</source>
        <comment>subscript: the depth the z-buffer holds</comment>
        <translation>stored</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="332"/>
        <source>the view-space z of P&apos;</source>
        <translation>the view-space z of P&apos;</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="332"/>
        <source>the NDC z</source>
        <translation>the NDC z</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="340"/>
        <source>&lt;b&gt;Z-buffer.&lt;/b&gt; Every pixel starts at %1. Each fragment&apos;s depth %2 (%3) is compared with the stored one; it is written, with its colour, only when %4. So far: %5 fragments tested, %6 written, %7 rejected.</source>
        <translation>&lt;b&gt;Z-buffer.&lt;/b&gt; Every pixel starts at %1. Each fragment&apos;s depth %2 (%3) is compared with the stored one; it is written, with its colour, only when %4. So far: %5 fragments tested, %6 written, %7 rejected.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="390"/>
        <source>%1 tested · %2 written · %3 rejected</source>
        <translation>%1 tested · %2 written · %3 rejected</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="399"/>
        <source>No frame yet.</source>
        <translation>No frame yet.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="416"/>
        <source>No pixel holds a triangle: the buffer is all clear value.</source>
        <translation>No pixel holds a triangle: the buffer is all clear value.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="423"/>
        <source>Drawn depths from %1 to %2; shown from %3 to %4.</source>
        <translation>Drawn depths from %1 to %2; shown from %3 to %4.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="429"/>
        <source>%1 pixels nearer and %2 farther than the range are drawn at its ends.</source>
        <translation>%1 pixels nearer and %2 farther than the range are drawn at its ends.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="443"/>
        <source>+inf</source>
        <translation>+inf</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="444"/>
        <source>x %1, y %2: no triangle; the depth stays at the clear value %3</source>
        <translation>x %1, y %2: no triangle; the depth stays at the clear value %3</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="449"/>
        <source>x %1, y %2: depth %3, triangle %4</source>
        <translation>x %1, y %2: depth %3, triangle %4</translation>
    </message>
</context>
</TS>
