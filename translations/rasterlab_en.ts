<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>rasterlab::MainWindow</name>
    <message>
        <location filename="../app/main_window.cpp" line="25"/>
        <source>Open Camera</source>
        <translation>Open Camera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="26"/>
        <source>Open Lighting</source>
        <translation>Open Lighting</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="27"/>
        <source>Open Object</source>
        <translation>Open Object</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="35"/>
        <source>Camera files (*.cfg *.txt);;All files (*)</source>
        <translation>Camera files (*.cfg *.txt);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="37"/>
        <source>Lighting files (*.txt *.lux);;All files (*)</source>
        <translation>Lighting files (*.txt *.lux);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="39"/>
        <source>Objects (*.byu *.txt);;All files (*)</source>
        <translation>Objects (*.byu *.txt);;All files (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="46"/>
        <source>%1 (built in)</source>
        <translation>%1 (built in)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="54"/>
        <source>RasterLab</source>
        <translation>RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="78"/>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="79"/>
        <source>Open &amp;Object...</source>
        <translation>Open &amp;Object...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="83"/>
        <source>Open &amp;Camera...</source>
        <translation>Open &amp;Camera...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="85"/>
        <source>Ctrl+Shift+C</source>
        <translation>Ctrl+Shift+C</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="87"/>
        <source>Open &amp;Lighting...</source>
        <translation>Open &amp;Lighting...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="88"/>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="89"/>
        <source>&amp;Default Scene</source>
        <translation>&amp;Default Scene</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="98"/>
        <source>&amp;Export PNG...</source>
        <translation>&amp;Export PNG...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="99"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="102"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="105"/>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="106"/>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Fit to Window</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="107"/>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="108"/>
        <source>&amp;Actual Size</source>
        <translation>&amp;Actual Size</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="109"/>
        <source>Ctrl+1</source>
        <translation>Ctrl+1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="110"/>
        <source>Zoom &amp;In</source>
        <translation>Zoom &amp;In</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="112"/>
        <source>Zoom &amp;Out</source>
        <translation>Zoom &amp;Out</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="117"/>
        <source>&amp;Shading</source>
        <translation>&amp;Shading</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="120"/>
        <source>&amp;Phong (per pixel)</source>
        <translation>&amp;Phong (per pixel)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="121"/>
        <source>&amp;Gouraud (per vertex)</source>
        <translation>&amp;Gouraud (per vertex)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="122"/>
        <source>&amp;Flat (per triangle)</source>
        <translation>&amp;Flat (per triangle)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="129"/>
        <source>Alt+%1</source>
        <translation>Alt+%1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="135"/>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="136"/>
        <source>&amp;About RasterLab</source>
        <translation>&amp;About RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="140"/>
        <source>Messages</source>
        <translation>Messages</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="148"/>
        <source>Scene</source>
        <translation>Scene</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="180"/>
        <source>%1: cannot export the image: %2</source>
        <translation>%1: cannot export the image: %2</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="181"/>
        <source>nothing has been rendered yet</source>
        <translation>nothing has been rendered yet</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="184"/>
        <source>Exported %1</source>
        <translation>Exported %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="190"/>
        <source>rendering...</source>
        <translation>rendering...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="197"/>
        <location filename="../app/main_window.cpp" line="254"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="205"/>
        <source>render failed</source>
        <translation>render failed</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="217"/>
        <source>Error: %1</source>
        <translation>Error: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="233"/>
        <source>Files</source>
        <translation>Files</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="235"/>
        <source>Camera</source>
        <translation>Camera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="236"/>
        <source>Lighting</source>
        <translation>Lighting</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="237"/>
        <source>Object</source>
        <translation>Object</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="239"/>
        <source>%1 vertices, %2 triangles; %3 x %4 pixels, %5 shading</source>
        <translation>%1 vertices, %2 triangles; %3 x %4 pixels, %5 shading</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="245"/>
        <source>Stages</source>
        <translation>Stages</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="246"/>
        <location filename="../app/main_window.cpp" line="260"/>
        <source>Camera basis</source>
        <translation>Camera basis</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="246"/>
        <source>View transform</source>
        <translation>View transform</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="246"/>
        <source>Normals</source>
        <translation>Normals</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="247"/>
        <source>Projection</source>
        <translation>Projection</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="247"/>
        <source>Scan conversion</source>
        <translation>Scan conversion</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="247"/>
        <source>Depth test</source>
        <translation>Depth test</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="248"/>
        <source>Shading</source>
        <translation>Shading</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="255"/>
        <source>skipped: %1</source>
        <translation>skipped: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="269"/>
        <source>largest orthonormality residual: %1</source>
        <translation>largest orthonormality residual: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="271"/>
        <source>Counts</source>
        <translation>Counts</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="272"/>
        <source>Triangles clipped at the near plane: %1; behind the camera: %2&lt;br&gt;</source>
        <translation>Triangles clipped at the near plane: %1; behind the camera: %2&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="275"/>
        <source>Zero-area triangles: %1 in view space, %2 on screen&lt;br&gt;</source>
        <translation>Zero-area triangles: %1 in view space, %2 on screen&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="278"/>
        <source>Fragments tested: %1; written: %2; rejected: %3&lt;br&gt;</source>
        <translation>Fragments tested: %1; written: %2; rejected: %3&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="282"/>
        <source>Pixels shaded: %1; normals turned toward the viewer: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; clamped at 255: %5</source>
        <translation>Pixels shaded: %1; normals turned toward the viewer: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; clamped at 255: %5</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="300"/>
        <source>empty (+inf)</source>
        <translation>empty (+inf)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="301"/>
        <source>x %1, y %2   RGB (%3, %4, %5)   depth %6</source>
        <translation>x %1, y %2   RGB (%3, %4, %5)   depth %6</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="317"/>
        <source>Export PNG</source>
        <translation>Export PNG</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="319"/>
        <source>PNG images (*.png)</source>
        <translation>PNG images (*.png)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="324"/>
        <source>About RasterLab</source>
        <translation>About RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="325"/>
        <source>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;The classic software rasterization pipeline, stage by stage: camera basis, view transform, normals, projection, scan conversion, depth test and shading.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;The classic software rasterization pipeline, stage by stage: camera basis, view transform, normals, projection, scan conversion, depth test and shading.&lt;/p&gt;</translation>
    </message>
</context>
</TS>
