<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_BR">
<context>
    <name>rasterlab::MainWindow</name>
    <message>
        <location filename="../app/main_window.cpp" line="26"/>
        <source>Open Camera</source>
        <translation>Abrir câmera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="28"/>
        <source>Open Lighting</source>
        <translation>Abrir iluminação</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="30"/>
        <source>Open Object</source>
        <translation>Abrir objeto</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="38"/>
        <source>Camera files (*.cfg *.txt);;All files (*)</source>
        <translation>Arquivos de câmera (*.cfg *.txt);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="40"/>
        <source>Lighting files (*.txt *.lux);;All files (*)</source>
        <translation>Arquivos de iluminação (*.txt *.lux);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="42"/>
        <source>Objects (*.byu *.txt);;All files (*)</source>
        <translation>Objetos (*.byu *.txt);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="51"/>
        <source>Detect from the file</source>
        <translation>Detectar pelo arquivo</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="57"/>
        <source>%1 (built in)</source>
        <translation>%1 (embutido)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="65"/>
        <source>RasterLab</source>
        <translation>RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="89"/>
        <source>&amp;File</source>
        <translation>&amp;Arquivo</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="90"/>
        <source>Open &amp;Object...</source>
        <translation>Abrir &amp;objeto...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="94"/>
        <source>Open &amp;Camera...</source>
        <translation>Abrir &amp;câmera...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="96"/>
        <source>Ctrl+Shift+C</source>
        <translation>Ctrl+Shift+C</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="98"/>
        <source>Open &amp;Lighting...</source>
        <translation>Abrir &amp;iluminação...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="99"/>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="100"/>
        <source>Open Command &amp;File...</source>
        <translation>Abrir arquivo de &amp;comandos...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="102"/>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="104"/>
        <source>&amp;Default Scene</source>
        <translation>Cena &amp;padrão</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="112"/>
        <source>Course File &amp;Layouts</source>
        <translation>&amp;Formatos dos arquivos do curso</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="114"/>
        <source>&amp;Camera</source>
        <translation>&amp;Câmera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="125"/>
        <source>&amp;Lighting</source>
        <translation>&amp;Iluminação</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="138"/>
        <source>&amp;Export PNG...</source>
        <translation>&amp;Exportar PNG...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="139"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="142"/>
        <source>&amp;Quit</source>
        <translation>&amp;Sair</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="145"/>
        <source>&amp;View</source>
        <translation>&amp;Exibir</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="146"/>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Ajustar à janela</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="147"/>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="149"/>
        <source>&amp;Actual Size</source>
        <translation>&amp;Tamanho real</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="150"/>
        <source>Ctrl+1</source>
        <translation>Ctrl+1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="151"/>
        <source>Zoom &amp;In</source>
        <translation>&amp;Aumentar zoom</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="153"/>
        <source>Zoom &amp;Out</source>
        <translation>&amp;Diminuir zoom</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="160"/>
        <source>&amp;Image</source>
        <translation>&amp;Imagem</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="163"/>
        <source>&amp;Shading</source>
        <translation>&amp;Tonalização</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="167"/>
        <source>&amp;Phong (per pixel)</source>
        <translation>&amp;Phong (por pixel)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="168"/>
        <source>&amp;Gouraud (per vertex)</source>
        <translation>&amp;Gouraud (por vértice)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="169"/>
        <source>&amp;Flat (per triangle)</source>
        <translation>&amp;Flat (por triângulo)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="176"/>
        <source>Alt+%1</source>
        <translation>Alt+%1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="182"/>
        <source>&amp;Help</source>
        <translation>A&amp;juda</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="183"/>
        <source>&amp;About RasterLab</source>
        <translation>&amp;Sobre o RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="187"/>
        <source>Messages</source>
        <translation>Mensagens</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="195"/>
        <source>Scene</source>
        <translation>Cena</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="269"/>
        <source>%1 - RasterLab</source>
        <translation>%1 - RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="284"/>
        <source>%1: cannot export the image: %2</source>
        <translation>%1: não foi possível exportar a imagem: %2</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="285"/>
        <source>nothing has been rendered yet</source>
        <translation>nada foi renderizado ainda</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="288"/>
        <source>Exported %1</source>
        <translation>Exportado %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="302"/>
        <source>rendering...</source>
        <translation>renderizando...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="302"/>
        <source>%1, rendering...</source>
        <translation>%1, renderizando...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="300"/>
        <location filename="../app/main_window.cpp" line="382"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="329"/>
        <source>Error: %1</source>
        <translation>Erro: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="345"/>
        <source>Files</source>
        <translation>Arquivos</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="348"/>
        <source>Command file</source>
        <translation>Arquivo de comandos</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="349"/>
        <source>Image</source>
        <translation>Imagem</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="351"/>
        <source>%1 vertices, %2 triangles in %3 draws; %4 x %5 pixels; %6 lights</source>
        <translation>%1 vértices, %2 triângulos em %3 desenhos; %4 x %5 pixels; %6 luzes</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="360"/>
        <source>Camera</source>
        <translation>Câmera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="361"/>
        <source>Lighting</source>
        <translation>Iluminação</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="362"/>
        <source>Object</source>
        <translation>Objeto</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="365"/>
        <source>%1 vertices, %2 triangles; %3 x %4 pixels, %5 shading</source>
        <translation>%1 vértices, %2 triângulos; %3 x %4 pixels, tonalização %5</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="373"/>
        <source>Stages</source>
        <translation>Etapas</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="374"/>
        <location filename="../app/main_window.cpp" line="388"/>
        <source>Camera basis</source>
        <translation>Base da câmera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="374"/>
        <source>View transform</source>
        <translation>Coordenadas de vista</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="374"/>
        <source>Normals</source>
        <translation>Normais</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="375"/>
        <source>Projection</source>
        <translation>Projeção</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="375"/>
        <source>Scan conversion</source>
        <translation>Conversão por varredura</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="375"/>
        <source>Depth test</source>
        <translation>Teste de profundidade (z-buffer)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="376"/>
        <source>Shading</source>
        <translation>Tonalização</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="383"/>
        <source>skipped: %1</source>
        <translation>omitida: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="397"/>
        <source>largest orthonormality residual: %1</source>
        <translation>maior resíduo de ortonormalidade: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="399"/>
        <source>Counts</source>
        <translation>Contagens</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="400"/>
        <source>Triangles clipped at the near plane: %1; behind the camera: %2&lt;br&gt;</source>
        <translation>Triângulos recortados no plano próximo: %1; atrás da câmera: %2&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="403"/>
        <source>Zero-area triangles: %1 in view space, %2 on screen&lt;br&gt;</source>
        <translation>Triângulos de área zero: %1 no espaço de vista, %2 na tela&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="406"/>
        <source>Fragments tested: %1; written: %2; rejected: %3&lt;br&gt;</source>
        <translation>Fragmentos testados: %1; escritos: %2; rejeitados: %3&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="410"/>
        <source>Pixels shaded: %1; normals turned toward the viewer: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; clamped at 255: %5</source>
        <translation>Pixels tonalizados: %1; normais invertidas para o observador: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; limitados a 255: %5</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="428"/>
        <source>empty (+inf)</source>
        <translation>vazio (+inf)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="429"/>
        <source>x %1, y %2   RGB (%3, %4, %5)   depth %6</source>
        <translation>x %1, y %2   RGB (%3, %4, %5)   profundidade %6</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="446"/>
        <source>Open Command File</source>
        <translation>Abrir arquivo de comandos</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="446"/>
        <source>Command files (*.txt);;All files (*)</source>
        <translation>Arquivos de comandos (*.txt);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="455"/>
        <source>Export PNG</source>
        <translation>Exportar PNG</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="456"/>
        <source>PNG images (*.png)</source>
        <translation>Imagens PNG (*.png)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="461"/>
        <source>About RasterLab</source>
        <translation>Sobre o RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="462"/>
        <source>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;The classic software rasterization pipeline, stage by stage: camera basis, view transform, normals, projection, scan conversion, depth test and shading.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;O pipeline clássico de rasterização por software, etapa por etapa: base da câmera, coordenadas de vista, normais, projeção, conversão por varredura, teste de profundidade e tonalização.&lt;/p&gt;</translation>
    </message>
</context>
</TS>
