<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_BR">
<context>
    <name>AccuracyPlot</name>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="126"/>
        <source>median time per frame (ms, log scale)</source>
        <translation>tempo mediano por quadro (ms, escala logarítmica)</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="132"/>
        <source>colour RMSE against the exact reference (byte steps, log scale)</source>
        <translation>RMSE da cor contra a referência exata (passos de byte, escala logarítmica)</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="186"/>
        <source>colour: shading</source>
        <translation>cor: tonalização</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="195"/>
        <source>shape: rules</source>
        <translation>forma: regras</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="204"/>
        <source>filled: float; hollow: double</source>
        <translation>cheio: float; vazado: double</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="207"/>
        <source>size: samples per pixel</source>
        <translation>tamanho: amostras por pixel</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="209"/>
        <source>exact reference:</source>
        <translation>referência exata:</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="211"/>
        <source>%1 ms, %2 rays</source>
        <translation>%1 ms, %2 raios</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="216"/>
        <source>an RMSE of 0 sits on the floor</source>
        <translation>RMSE 0: no piso do gráfico</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="261"/>
        <source>byte steps</source>
        <translation>passos de byte</translation>
    </message>
    <message>
        <location filename="../app/accuracy_plot.cpp" line="264"/>
        <source>coverage</source>
        <translation>cobertura</translation>
    </message>
</context>
<context>
    <name>rasterlab::AccuracyPanel</name>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="40"/>
        <source>&amp;Measure</source>
        <translation>&amp;Medir</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="43"/>
        <source>Render the scene in every mode and compare each with an exact ray-cast reference</source>
        <translation>Renderiza a cena em cada modo e compara cada um com uma referência exata por lançamento de raios</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="45"/>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="50"/>
        <source>1 sample a pixel</source>
        <translation>1 amostra por pixel</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="51"/>
        <source>also 2x2 samples</source>
        <translation>também 2x2 amostras</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="52"/>
        <source>also 4x4 samples</source>
        <translation>também 4x4 amostras</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="57"/>
        <source>Measures the error of each mode against an exact reference.</source>
        <translation>Mede o erro de cada modo contra uma referência exata.</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="64"/>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="64"/>
        <source>Rules</source>
        <translation>Regras</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="64"/>
        <source>Precision</source>
        <translation>Precisão</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="64"/>
        <source>Samples</source>
        <translation>Amostras</translation>
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
        <translation>Erro máximo</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="65"/>
        <source>Within 1/255</source>
        <translation>Dentro de 1/255</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="66"/>
        <source>Errors in byte steps (1/255) over the pixels both images cover</source>
        <translation>Erros em passos de byte (1/255) nos pixels que as duas imagens cobrem</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="87"/>
        <source>Click a pixel to compare the mode with the reference there</source>
        <translation>Clique num pixel para comparar ali o modo com a referência</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="120"/>
        <source>The scene changed: measure again.</source>
        <translation>A cena mudou: meça de novo.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/accuracy_panel.cpp" line="142"/>
        <source>Measuring %n mode(s) against the exact reference...</source>
        <translation>
            <numerusform>Medindo %n modo contra a referência exata...</numerusform>
            <numerusform>Medindo %n modos contra a referência exata...</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="177"/>
        <source>Cancelled.</source>
        <translation>Cancelado.</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="178"/>
        <source>The measurement failed: %1</source>
        <translation>A medição falhou: %1</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="184"/>
        <source>%1 at %2x%3: %4 modes; the exact reference cast %5 rays in %6 ms.</source>
        <translation>%1 em %2x%3: %4 modos; a referência exata lançou %5 raios em %6 ms.</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="211"/>
        <source>Error against run time: %1, %2x%3</source>
        <translation>Erro contra tempo de execução: %1, %2x%3</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="258"/>
        <source>%1 (%2): coverage differs on %3 pixels (%4); the largest error, %5 byte steps, is at (%6, %7). Click the map to compare a pixel.</source>
        <translation>%1 (%2): a cobertura difere em %3 pixels (%4); o maior erro, %5 passos de byte, está em (%6, %7). Clique no mapa para comparar um pixel.</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="277"/>
        <source>Pixel (%1, %2), %3: mode %4, reference %5, difference %6 (byte steps).</source>
        <translation>Pixel (%1, %2), %3: modo %4, referência %5, diferença %6 (passos de byte).</translation>
    </message>
    <message>
        <location filename="../app/accuracy_panel.cpp" line="283"/>
        <source>Coverage differs: %1 of %2 samples covered by the mode, %3 by the reference.</source>
        <translation>A cobertura difere: %1 de %2 amostras cobertas pelo modo, %3 pela referência.</translation>
    </message>
</context>
<context>
    <name>rasterlab::MainWindow</name>
    <message>
        <location filename="../app/main_window.cpp" line="30"/>
        <source>Open Camera</source>
        <translation>Abrir câmera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="32"/>
        <source>Open Lighting</source>
        <translation>Abrir iluminação</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="34"/>
        <source>Open Object</source>
        <translation>Abrir objeto</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="42"/>
        <source>Camera files (*.cfg *.txt);;All files (*)</source>
        <translation>Arquivos de câmera (*.cfg *.txt);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="44"/>
        <source>Lighting files (*.txt *.lux);;All files (*)</source>
        <translation>Arquivos de iluminação (*.txt *.lux);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="46"/>
        <source>Objects (*.byu *.txt);;All files (*)</source>
        <translation>Objetos (*.byu *.txt);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="55"/>
        <source>Detect from the file</source>
        <translation>Detectar pelo arquivo</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="61"/>
        <source>%1 (built in)</source>
        <translation>%1 (embutido)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="69"/>
        <source>RasterLab</source>
        <translation>RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="95"/>
        <source>&amp;File</source>
        <translation>&amp;Arquivo</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="96"/>
        <source>Open &amp;Object...</source>
        <translation>Abrir &amp;objeto...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="100"/>
        <source>Open &amp;Camera...</source>
        <translation>Abrir &amp;câmera...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="102"/>
        <source>Ctrl+Shift+C</source>
        <translation>Ctrl+Shift+C</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="104"/>
        <source>Open &amp;Lighting...</source>
        <translation>Abrir &amp;iluminação...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="105"/>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="107"/>
        <source>Open Command &amp;File...</source>
        <translation>Abrir arquivo de &amp;comandos...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="108"/>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="110"/>
        <source>&amp;Default Scene</source>
        <translation>Cena &amp;padrão</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="118"/>
        <source>Course File &amp;Layouts</source>
        <translation>&amp;Formatos dos arquivos do curso</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="120"/>
        <source>&amp;Camera</source>
        <translation>&amp;Câmera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="132"/>
        <source>&amp;Lighting</source>
        <translation>&amp;Iluminação</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="145"/>
        <source>&amp;Export PNG...</source>
        <translation>&amp;Exportar PNG...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="146"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="149"/>
        <source>&amp;Quit</source>
        <translation>&amp;Sair</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="152"/>
        <source>&amp;View</source>
        <translation>&amp;Exibir</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="153"/>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Ajustar à janela</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="154"/>
        <source>Ctrl+0</source>
        <translation>Ctrl+0</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="156"/>
        <source>&amp;Actual Size</source>
        <translation>&amp;Tamanho real</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="157"/>
        <source>Ctrl+1</source>
        <translation>Ctrl+1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="158"/>
        <source>Zoom &amp;In</source>
        <translation>&amp;Aumentar zoom</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="160"/>
        <source>Zoom &amp;Out</source>
        <translation>&amp;Diminuir zoom</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="165"/>
        <source>Reset &amp;Layout</source>
        <translation>Restaurar &amp;Layout</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="169"/>
        <source>&amp;Image</source>
        <translation>&amp;Imagem</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="172"/>
        <source>&amp;Shading</source>
        <translation>&amp;Tonalização</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="176"/>
        <source>&amp;Phong (per pixel)</source>
        <translation>&amp;Phong (por pixel)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="177"/>
        <source>&amp;Gouraud (per vertex)</source>
        <translation>&amp;Gouraud (por vértice)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="178"/>
        <source>&amp;Flat (per triangle)</source>
        <translation>&amp;Flat (por triângulo)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="185"/>
        <source>Alt+%1</source>
        <translation>Alt+%1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="192"/>
        <source>&amp;Rasterization Rules</source>
        <translation>&amp;Regras de rasterização</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="196"/>
        <source>&amp;Course (seed 000: whole-pixel vertices, screen-space interpolation)</source>
        <translation>&amp;Curso (semente 000: vértices em pixels inteiros, interpolação no espaço da tela)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="198"/>
        <source>&amp;GPU-like (1/256-pixel vertices, pixel centres, top-left rule, perspective-correct)</source>
        <translation>&amp;Como uma GPU (vértices em 1/256 de pixel, centros dos pixels, regra top-left, correção de perspectiva)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="200"/>
        <source>&amp;HW2 (seed 001&apos;s reference images)</source>
        <translation>&amp;HW2 (as imagens de referência da semente 001)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="212"/>
        <source>&amp;Help</source>
        <translation>A&amp;juda</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="213"/>
        <source>&amp;About RasterLab</source>
        <translation>&amp;Sobre o RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="217"/>
        <source>Messages</source>
        <translation>Mensagens</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="225"/>
        <source>Scene</source>
        <translation>Cena</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="231"/>
        <source>Accuracy</source>
        <translation>Exatidão</translation>
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
        <translation>%1: não foi possível exportar a imagem: %2</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="353"/>
        <source>nothing has been rendered yet</source>
        <translation>nada foi renderizado ainda</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="356"/>
        <source>Exported %1</source>
        <translation>Exportado %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="379"/>
        <source>rendering...</source>
        <translation>renderizando...</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="379"/>
        <source>%1, rendering...</source>
        <translation>%1, renderizando...</translation>
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
        <translation>Erro: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="423"/>
        <source>Files</source>
        <translation>Arquivos</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="426"/>
        <source>Command file</source>
        <translation>Arquivo de comandos</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="427"/>
        <source>Image</source>
        <translation>Imagem</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="429"/>
        <source>%1 vertices, %2 triangles in %3 draws; %4 x %5 pixels; %6 lights</source>
        <translation>%1 vértices, %2 triângulos em %3 desenhos; %4 x %5 pixels; %6 luzes</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="439"/>
        <source>Camera</source>
        <translation>Câmera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="440"/>
        <source>Lighting</source>
        <translation>Iluminação</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="441"/>
        <source>Object</source>
        <translation>Objeto</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="443"/>
        <source>%1 vertices, %2 triangles; %3 x %4 pixels, %5 shading</source>
        <translation>%1 vértices, %2 triângulos; %3 x %4 pixels, tonalização %5</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="451"/>
        <source>Stages</source>
        <translation>Etapas</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="452"/>
        <location filename="../app/main_window.cpp" line="466"/>
        <source>Camera basis</source>
        <translation>Base da câmera</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="452"/>
        <source>View transform</source>
        <translation>Coordenadas de vista</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="452"/>
        <source>Normals</source>
        <translation>Normais</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="453"/>
        <source>Projection</source>
        <translation>Projeção</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="453"/>
        <source>Scan conversion</source>
        <translation>Conversão por varredura</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="453"/>
        <source>Depth test</source>
        <translation>Teste de profundidade (z-buffer)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="454"/>
        <source>Shading</source>
        <translation>Tonalização</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="461"/>
        <source>skipped: %1</source>
        <translation>omitida: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="475"/>
        <source>largest orthonormality residual: %1</source>
        <translation>maior resíduo de ortonormalidade: %1</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="477"/>
        <source>Counts</source>
        <translation>Contagens</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="478"/>
        <source>Triangles clipped at the near plane: %1; behind the camera: %2&lt;br&gt;</source>
        <translation>Triângulos recortados no plano próximo: %1; atrás da câmera: %2&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="481"/>
        <source>Zero-area triangles: %1 in view space, %2 on screen&lt;br&gt;</source>
        <translation>Triângulos de área zero: %1 no espaço de vista, %2 na tela&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="484"/>
        <source>Fragments tested: %1; written: %2; rejected: %3&lt;br&gt;</source>
        <translation>Fragmentos testados: %1; escritos: %2; rejeitados: %3&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="488"/>
        <source>Pixels shaded: %1; normals turned toward the viewer: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; clamped at 255: %5</source>
        <translation>Pixels tonalizados: %1; normais invertidas para o observador: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; limitados a 255: %5</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="506"/>
        <source>empty (+inf)</source>
        <translation>vazio (+inf)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="507"/>
        <source>x %1, y %2   RGB (%3, %4, %5)   depth %6</source>
        <translation>x %1, y %2   RGB (%3, %4, %5)   profundidade %6</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="523"/>
        <source>Open Command File</source>
        <translation>Abrir arquivo de comandos</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="524"/>
        <source>Command files (*.txt);;All files (*)</source>
        <translation>Arquivos de comandos (*.txt);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="534"/>
        <source>Export PNG</source>
        <translation>Exportar PNG</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="534"/>
        <source>PNG images (*.png)</source>
        <translation>Imagens PNG (*.png)</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="539"/>
        <source>About RasterLab</source>
        <translation>Sobre o RasterLab</translation>
    </message>
    <message>
        <location filename="../app/main_window.cpp" line="540"/>
        <source>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;The classic software rasterization pipeline, stage by stage: camera basis, view transform, normals, projection, scan conversion, depth test and shading.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;O pipeline clássico de rasterização por software, etapa por etapa: base da câmera, coordenadas de vista, normais, projeção, conversão por varredura, teste de profundidade e tonalização.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>rasterlab::ZBufferView</name>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="155"/>
        <source>Automatic range (nearest to farthest drawn)</source>
        <translation>Faixa automática (do mais próximo ao mais distante desenhado)</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="170"/>
        <source>Grey (near white)</source>
        <translation>Cinza (perto = branco)</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="171"/>
        <source>False colour (near red, far blue)</source>
        <translation>Cores falsas (perto vermelho, longe azul)</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="182"/>
        <source>Nearest (white / red):</source>
        <translation>Mais próximo (branco / vermelho):</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="183"/>
        <source>Farthest (dark / blue):</source>
        <translation>Mais distante (escuro / azul):</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="184"/>
        <source>Colours:</source>
        <translation>Cores:</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="254"/>
        <source>No frame yet.</source>
        <translation>Nenhum quadro ainda.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="271"/>
        <source>No pixel holds a triangle: the buffer is all clear value.</source>
        <translation>Nenhum pixel contém um triângulo: o buffer inteiro está no valor de limpeza.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="274"/>
        <source>Drawn depths from %1 to %2; shown from %3 to %4.</source>
        <translation>Profundidades desenhadas de %1 a %2; exibidas de %3 a %4.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="280"/>
        <source>%1 pixels nearer and %2 farther than the range are drawn at its ends.</source>
        <translation>%1 pixels mais próximos e %2 mais distantes que a faixa aparecem nas suas extremidades.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="294"/>
        <source>+inf</source>
        <translation>+inf</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="295"/>
        <source>x %1, y %2: no triangle; the depth stays at the clear value %3</source>
        <translation>x %1, y %2: nenhum triângulo; a profundidade fica no valor de limpeza %3</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="300"/>
        <source>x %1, y %2: depth %3, triangle %4</source>
        <translation>x %1, y %2: profundidade %3, triângulo %4</translation>
    </message>
</context>
</TS>
