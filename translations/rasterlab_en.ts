<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>AccuracyPlot</name>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="126"/>
        <source>median time per frame (ms, log scale)</source>
        <translation>median time per frame (ms, log scale)</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="132"/>
        <source>colour RMSE against the exact reference (byte steps, log scale)</source>
        <translation>colour RMSE against the exact reference (byte steps, log scale)</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="186"/>
        <source>colour: shading</source>
        <translation>colour: shading</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="195"/>
        <source>shape: rules</source>
        <translation>shape: rules</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="204"/>
        <source>filled: float; hollow: double</source>
        <translation>filled: float; hollow: double</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="207"/>
        <source>size: samples per pixel</source>
        <translation>size: samples per pixel</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="209"/>
        <source>exact reference:</source>
        <translation>exact reference:</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="211"/>
        <source>%1 ms, %2 rays</source>
        <translation>%1 ms, %2 rays</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="216"/>
        <source>an RMSE of 0 sits on the floor</source>
        <translation>an RMSE of 0 sits on the floor</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="261"/>
        <source>byte steps</source>
        <translation>byte steps</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="264"/>
        <source>coverage</source>
        <translation>coverage</translation>
    </message>
</context>
<context>
    <name>rasterlab::AccuracyPanel</name>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="40"/>
        <source>&amp;Measure</source>
        <translation>&amp;Measure</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="43"/>
        <source>Render the scene in every mode and compare each with an exact ray-cast reference</source>
        <translation>Render the scene in every mode and compare each with an exact ray-cast reference</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="45"/>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="50"/>
        <source>1 sample a pixel</source>
        <translation>1 sample a pixel</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="51"/>
        <source>also 2x2 samples</source>
        <translation>also 2x2 samples</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="52"/>
        <source>also 4x4 samples</source>
        <translation>also 4x4 samples</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="57"/>
        <source>Measures the error of each mode against an exact reference.</source>
        <translation>Measures the error of each mode against an exact reference.</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="64"/>
        <source>Mode</source>
        <translation>Mode</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="64"/>
        <source>Rules</source>
        <translation>Rules</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="64"/>
        <source>Precision</source>
        <translation>Precision</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="64"/>
        <source>Samples</source>
        <translation>Samples</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="65"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="65"/>
        <source>RMSE</source>
        <translation>RMSE</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="65"/>
        <source>Max error</source>
        <translation>Max error</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="65"/>
        <source>Within 1/255</source>
        <translation>Within 1/255</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="66"/>
        <source>Errors in byte steps (1/255) over the pixels both images cover</source>
        <translation>Errors in byte steps (1/255) over the pixels both images cover</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="87"/>
        <source>Click a pixel to compare the mode with the reference there</source>
        <translation>Click a pixel to compare the mode with the reference there</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="120"/>
        <source>The scene changed: measure again.</source>
        <translation>The scene changed: measure again.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/accuracy_panel.cpp" line="142"/>
        <source>Measuring %n mode(s) against the exact reference...</source>
        <translation>
            <numerusform>Measuring %n mode against the exact reference...</numerusform>
            <numerusform>Measuring %n modes against the exact reference...</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="177"/>
        <source>Cancelled.</source>
        <translation>Cancelled.</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="178"/>
        <source>The measurement failed: %1</source>
        <translation>The measurement failed: %1</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="184"/>
        <source>%1 at %2x%3: %4 modes; the exact reference cast %5 rays in %6 ms.</source>
        <translation>%1 at %2x%3: %4 modes; the exact reference cast %5 rays in %6 ms.</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="211"/>
        <source>Error against run time: %1, %2x%3</source>
        <translation>Error against run time: %1, %2x%3</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="258"/>
        <source>%1 (%2): coverage differs on %3 pixels (%4); the largest error, %5 byte steps, is at (%6, %7). Click the map to compare a pixel.</source>
        <translation>%1 (%2): coverage differs on %3 pixels (%4); the largest error, %5 byte steps, is at (%6, %7). Click the map to compare a pixel.</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="277"/>
        <source>Pixel (%1, %2), %3: mode %4, reference %5, difference %6 (byte steps).</source>
        <translation>Pixel (%1, %2), %3: mode %4, reference %5, difference %6 (byte steps).</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="283"/>
        <source>Coverage differs: %1 of %2 samples covered by the mode, %3 by the reference.</source>
        <translation>Coverage differs: %1 of %2 samples covered by the mode, %3 by the reference.</translation>
    </message>
</context>
<context>
    <name>rasterlab::MainWindow</name>
    <message>
        <location filename="../app/main_window.cpp" line="30"/>
        <source>Open Camera</source>
        <translation>Open Camera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="32"/>
        <source>Open Lighting</source>
        <translation>Open Lighting</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="34"/>
        <source>Open Object</source>
        <translation>Open Object</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="42"/>
        <source>Camera files (*.cfg *.txt);;All files (*)</source>
        <translation>Camera files (*.cfg *.txt);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="44"/>
        <source>Lighting files (*.txt *.lux);;All files (*)</source>
        <translation>Lighting files (*.txt *.lux);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="46"/>
        <source>Objects (*.byu *.txt);;All files (*)</source>
        <translation>Objects (*.byu *.txt);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="55"/>
        <source>Detect from the file</source>
        <translation>Detect from the file</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="61"/>
        <source>%1 (built in)</source>
        <translation>%1 (built in)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="69"/>
        <source>RasterLab</source>
        <translation>RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="95"/>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="96"/>
        <source>Open &amp;Object...</source>
        <translation>Open &amp;Object...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="100"/>
        <source>Open &amp;Camera...</source>
        <translation>Open &amp;Camera...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="102"/>
        <source>Ctrl+Shift+C</source>
        <translation>Ctrl+Shift+C</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="104"/>
        <source>Open &amp;Lighting...</source>
        <translation>Open &amp;Lighting...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="105"/>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="107"/>
        <source>Open Command &amp;File...</source>
        <translation>Open Command &amp;File...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="108"/>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="110"/>
        <source>&amp;Default Scene</source>
        <translation>&amp;Default Scene</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="118"/>
        <source>Course File &amp;Layouts</source>
        <translation>Course File &amp;Layouts</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="120"/>
        <source>&amp;Camera</source>
        <translation>&amp;Camera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="132"/>
        <source>&amp;Lighting</source>
        <translation>&amp;Lighting</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="145"/>
        <source>&amp;Export PNG...</source>
        <translation>&amp;Export PNG...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="146"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="149"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="152"/>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="153"/>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Fit to Window</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="154"/>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="156"/>
        <source>&amp;Actual Size</source>
        <translation>&amp;Actual Size</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="157"/>
        <source>Ctrl+1</source>
        <translation>Ctrl+1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="158"/>
        <source>Zoom &amp;In</source>
        <translation>Zoom &amp;In</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="160"/>
        <source>Zoom &amp;Out</source>
        <translation>Zoom &amp;Out</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="165"/>
        <source>Reset &amp;Layout</source>
        <translation>Reset &amp;Layout</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="169"/>
        <source>&amp;Image</source>
        <translation>&amp;Image</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="172"/>
        <source>&amp;Shading</source>
        <translation>&amp;Shading</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="176"/>
        <source>&amp;Phong (per pixel)</source>
        <translation>&amp;Phong (per pixel)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="177"/>
        <source>&amp;Gouraud (per vertex)</source>
        <translation>&amp;Gouraud (per vertex)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="178"/>
        <source>&amp;Flat (per triangle)</source>
        <translation>&amp;Flat (per triangle)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="185"/>
        <source>Alt+%1</source>
        <translation>Alt+%1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="192"/>
        <source>&amp;Rasterization Rules</source>
        <translation>&amp;Rasterization Rules</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="196"/>
        <source>&amp;Course (seed 000: whole-pixel vertices, screen-space interpolation)</source>
        <translation>&amp;Course (seed 000: whole-pixel vertices, screen-space interpolation)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="198"/>
        <source>&amp;GPU-like (1/256-pixel vertices, pixel centres, top-left rule, perspective-correct)</source>
        <translation>&amp;GPU-like (1/256-pixel vertices, pixel centres, top-left rule, perspective-correct)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="200"/>
        <source>&amp;HW2 (seed 001&apos;s reference images)</source>
        <translation>&amp;HW2 (seed 001&apos;s reference images)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="212"/>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="213"/>
        <source>&amp;About RasterLab</source>
        <translation>&amp;About RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="217"/>
        <source>Messages</source>
        <translation>Messages</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="225"/>
        <source>Scene</source>
        <translation>Scene</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="231"/>
        <source>Accuracy</source>
        <translation>Accuracy</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="237"/>
        <source>Z-buffer</source>
        <translation>Z-buffer</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="337"/>
        <source>%1 - RasterLab</source>
        <translation>%1 - RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="352"/>
        <source>%1: cannot export the image: %2</source>
        <translation>%1: cannot export the image: %2</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="353"/>
        <source>nothing has been rendered yet</source>
        <translation>nothing has been rendered yet</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="356"/>
        <source>Exported %1</source>
        <translation>Exported %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="379"/>
        <source>rendering...</source>
        <translation>rendering...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="379"/>
        <source>%1, rendering...</source>
        <translation>%1, rendering...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="377"/>
        <location filename="../app/main_window.cpp" line="460"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="407"/>
        <source>Error: %1</source>
        <translation>Error: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="423"/>
        <source>Files</source>
        <translation>Files</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="426"/>
        <source>Command file</source>
        <translation>Command file</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="427"/>
        <source>Image</source>
        <translation>Image</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="429"/>
        <source>%1 vertices, %2 triangles in %3 draws; %4 x %5 pixels; %6 lights</source>
        <translation>%1 vertices, %2 triangles in %3 draws; %4 x %5 pixels; %6 lights</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="439"/>
        <source>Camera</source>
        <translation>Camera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="440"/>
        <source>Lighting</source>
        <translation>Lighting</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="441"/>
        <source>Object</source>
        <translation>Object</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="443"/>
        <source>%1 vertices, %2 triangles; %3 x %4 pixels, %5 shading</source>
        <translation>%1 vertices, %2 triangles; %3 x %4 pixels, %5 shading</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="451"/>
        <source>Stages</source>
        <translation>Stages</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="452"/>
        <location filename="../app/main_window.cpp" line="466"/>
        <source>Camera basis</source>
        <translation>Camera basis</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="452"/>
        <source>View transform</source>
        <translation>View transform</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="452"/>
        <source>Normals</source>
        <translation>Normals</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="453"/>
        <source>Projection</source>
        <translation>Projection</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="453"/>
        <source>Scan conversion</source>
        <translation>Scan conversion</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="453"/>
        <source>Depth test</source>
        <translation>Depth test</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="454"/>
        <source>Shading</source>
        <translation>Shading</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="461"/>
        <source>skipped: %1</source>
        <translation>skipped: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="475"/>
        <source>largest orthonormality residual: %1</source>
        <translation>largest orthonormality residual: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="477"/>
        <source>Counts</source>
        <translation>Counts</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="478"/>
        <source>Triangles clipped at the near plane: %1; behind the camera: %2&lt;br&gt;</source>
        <translation>Triangles clipped at the near plane: %1; behind the camera: %2&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="481"/>
        <source>Zero-area triangles: %1 in view space, %2 on screen&lt;br&gt;</source>
        <translation>Zero-area triangles: %1 in view space, %2 on screen&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="484"/>
        <source>Fragments tested: %1; written: %2; rejected: %3&lt;br&gt;</source>
        <translation>Fragments tested: %1; written: %2; rejected: %3&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="488"/>
        <source>Pixels shaded: %1; normals turned toward the viewer: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; clamped at 255: %5</source>
        <translation>Pixels shaded: %1; normals turned toward the viewer: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; clamped at 255: %5</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="506"/>
        <source>empty (+inf)</source>
        <translation>empty (+inf)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="507"/>
        <source>x %1, y %2   RGB (%3, %4, %5)   depth %6</source>
        <translation>x %1, y %2   RGB (%3, %4, %5)   depth %6</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="523"/>
        <source>Open Command File</source>
        <translation>Open Command File</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="524"/>
        <source>Command files (*.txt);;All files (*)</source>
        <translation>Command files (*.txt);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="534"/>
        <source>Export PNG</source>
        <translation>Export PNG</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="534"/>
        <source>PNG images (*.png)</source>
        <translation>PNG images (*.png)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="539"/>
        <source>About RasterLab</source>
        <translation>About RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="540"/>
        <source>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;The classic software rasterization pipeline, stage by stage: camera basis, view transform, normals, projection, scan conversion, depth test and shading.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;The classic software rasterization pipeline, stage by stage: camera basis, view transform, normals, projection, scan conversion, depth test and shading.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>rasterlab::ZBufferView</name>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="155"/>
        <source>Automatic range (nearest to farthest drawn)</source>
        <translation>Automatic range (nearest to farthest drawn)</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="170"/>
        <source>Grey (near white)</source>
        <translation>Grey (near white)</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="171"/>
        <source>False colour (near red, far blue)</source>
        <translation>False colour (near red, far blue)</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="182"/>
        <source>Nearest (white / red):</source>
        <translation>Nearest (white / red):</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="183"/>
        <source>Farthest (dark / blue):</source>
        <translation>Farthest (dark / blue):</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="184"/>
        <source>Colours:</source>
        <translation>Colours:</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="254"/>
        <source>No frame yet.</source>
        <translation>No frame yet.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="271"/>
        <source>No pixel holds a triangle: the buffer is all clear value.</source>
        <translation>No pixel holds a triangle: the buffer is all clear value.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="274"/>
        <source>Drawn depths from %1 to %2; shown from %3 to %4.</source>
        <translation>Drawn depths from %1 to %2; shown from %3 to %4.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="280"/>
        <source>%1 pixels nearer and %2 farther than the range are drawn at its ends.</source>
        <translation>%1 pixels nearer and %2 farther than the range are drawn at its ends.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="294"/>
        <source>+inf</source>
        <translation>+inf</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="295"/>
        <source>x %1, y %2: no triangle; the depth stays at the clear value %3</source>
        <translation>x %1, y %2: no triangle; the depth stays at the clear value %3</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="300"/>
        <source>x %1, y %2: depth %3, triangle %4</source>
        <translation>x %1, y %2: depth %3, triangle %4</translation>
    </message>
</context>
</TS>
