<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_BR">
<context>
    <name>AccuracyPlot</name>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="126"/>
        <source>median time per frame (ms, log scale)</source>
        <translation>tempo mediano por quadro (ms, escala logarítmica)</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="132"/>
        <source>colour RMSE against the exact reference (byte steps, log scale)</source>
        <translation>RMSE da cor contra a referência exata (passos de byte, escala logarítmica)</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="186"/>
        <source>colour: shading</source>
        <translation>cor: sombreamento</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="195"/>
        <source>shape: rules</source>
        <translation>forma: regras</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="204"/>
        <source>filled: float; hollow: double</source>
        <translation>cheio: float; vazado: double</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="207"/>
        <source>size: samples per pixel</source>
        <translation>tamanho: amostras por pixel</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="209"/>
        <source>exact reference:</source>
        <translation>referência exata:</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="211"/>
        <source>%1 ms, %2 rays</source>
        <translation>%1 ms, %2 raios</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="216"/>
        <source>an RMSE of 0 sits on the floor</source>
        <translation>RMSE 0: no piso do gráfico</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="261"/>
        <source>byte steps</source>
        <translation>passos de byte</translation>
    </message>
    <message>
        <location filename="../app/plots/accuracy_plot.cpp" line="264"/>
        <source>coverage</source>
        <translation>cobertura</translation>
    </message>
</context>
<context>
    <name>Lessons</name>
    <message>
        <location filename="../app/documents/examples.cpp" line="29"/>
        <source>One triangle</source>
        <translation>Um triângulo</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="30"/>
        <source>A single triangle in a 32 x 24 image, large enough to read from the back of the room. Step by pixel (Page Down, or Right and Left in presentation mode, F5) and watch the scanline fill from its left edge to its right; pick a pixel to see its barycentric coordinates, its interpolated P and N, and its Phong terms in the pixel inspector.</source>
        <translation>Um único triângulo numa imagem de 32 x 24, grande o bastante para ser lido do fundo da sala. Avance por pixel (Page Down, ou as setas para a direita e a esquerda no modo de apresentação, F5) e veja a linha de varredura se preencher da aresta esquerda até a direita; escolha um pixel para ver no inspetor de pixel as suas coordenadas baricêntricas, o P e o N interpolados e os termos de Phong.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="39"/>
        <source>Two triangles that cross (the z-buffer)</source>
        <translation>Dois triângulos que se cruzam (o z-buffer)</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="40"/>
        <source>Two triangles that pass through each other: each is nearer the camera over half of the other, so no order of whole triangles draws them right. It opens at the start of the frame with a breakpoint at the second triangle: Continue to Breakpoint (F8) draws the first, then step by scanline through the second and watch the z-buffer dock: its pixels are kept above the crossing line and rejected below it. Pick a pixel near the crossing to compare both depths.</source>
        <translation>Dois triângulos que se atravessam: cada um está mais perto da câmera em metade do outro, então nenhuma ordem de triângulos inteiros os desenha certo. Abre no início do quadro com um ponto de parada no segundo triângulo: Continuar até o ponto de parada (F8) desenha o primeiro; depois avance por linha de varredura pelo segundo e observe o painel do z-buffer: os seus pixels ficam acima da linha de cruzamento e são rejeitados abaixo dela. Escolha um pixel perto do cruzamento para comparar as duas profundidades.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="51"/>
        <source>A triangle through the near plane</source>
        <translation>Um triângulo que atravessa o plano próximo</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="52"/>
        <source>A triangle on the floor whose far corner is behind the camera. The near-plane clipping dock shows it cut at the near plane into a quad, and the quad split into two triangles. Then choose Shading &gt; Projection &gt; Plain Divide: the corner behind the eye is divided by a negative z and lands above the horizon.</source>
        <translation>Um triângulo no chão com um vértice atrás da câmera. O painel de recorte no plano próximo mostra-o cortado no plano próximo num quadrilátero, e o quadrilátero dividido em dois triângulos. Depois escolha Sombreamento &gt; Projeção &gt; Divisão simples: o vértice atrás do olho é dividido por um z negativo e vai parar acima do horizonte.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="60"/>
        <source>A goblet turned from a profile</source>
        <translation>Uma taça torneada a partir de um perfil</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="61"/>
        <source>A goblet made by turning a profile around the y axis (the course&apos;s chalice idea, 1,520 triangles of our own). Start at the camera basis dock, then follow the stages in order: view coordinates, normals, projection, scan conversion, z-buffer and lighting. Pick a pixel on the highlight of the bowl to see why it is bright.</source>
        <translation>Uma taça feita girando um perfil em torno do eixo y (a ideia do cálice do curso, com 1.520 triângulos nossos). Comece pelo painel da base da câmera e siga as etapas em ordem: coordenadas de vista, normais, projeção, conversão por varredura, z-buffer e iluminação. Escolha um pixel no brilho do bojo para ver por que ele é claro.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="69"/>
        <source>A low-polygon sphere: flat, Gouraud, Phong</source>
        <translation>Uma esfera de poucos polígonos: plano, Gouraud, Phong</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="70"/>
        <source>A sphere of 168 triangles. It opens in flat shading, one colour per triangle; press the Shading menu&apos;s Gouraud and then Phong to compare (File &gt; Export More &gt; Shading Side by Side puts the three in one picture). Gouraud smooths the facets but blurs the highlight; Phong draws it round.</source>
        <translation>Uma esfera de 168 triângulos. Abre em sombreamento plano, uma cor por triângulo; escolha Gouraud e depois Phong no menu Sombreamento para comparar (Arquivo &gt; Exportar mais &gt; Sombreamentos lado a lado põe os três numa só figura). Gouraud suaviza as faces mas borra o brilho; Phong o desenha redondo.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="78"/>
        <source>Several lights: spot, directional, attenuated</source>
        <translation>Várias luzes: spot, direcional, atenuada</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="79"/>
        <source>A floor and a ball under three lights of the lecture slides: a yellow spot (the bright disc, with a soft edge from its exponent), a dim blue directional light from the right, and a red positional light whose strength falls with distance. Pick pixels inside and outside the spot&apos;s cone and compare the pixel inspector&apos;s terms light by light; change the lights in the Edit dock.</source>
        <translation>Um chão e uma bola sob três luzes dos slides da aula: um spot amarelo (o disco claro, com a borda suave do seu expoente), uma luz direcional azul e fraca vinda da direita e uma luz pontual vermelha cuja intensidade cai com a distância. Escolha pixels dentro e fora do cone do spot e compare os termos do inspetor de pixel luz a luz; mude as luzes no painel Edição.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="88"/>
        <source>Three triangles in a cycle (the painter)</source>
        <translation>Três triângulos em ciclo (o pintor)</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="89"/>
        <source>Three triangles that each lie in front of the next: no order of whole triangles can draw them right, so the painter&apos;s algorithm (far to near by barycentre) must fail somewhere. Step by triangle and see one painted over a nearer one; the painter&apos;s algorithm dock marks the pixels that differ from the z-buffer&apos;s image.</source>
        <translation>Três triângulos, cada um à frente do seguinte: nenhuma ordem de triângulos inteiros consegue desenhá-los certo, então o algoritmo do pintor (do mais longe ao mais perto, pelo baricentro) tem de falhar em algum lugar. Avance por triângulo e veja um deles pintado sobre outro mais próximo; o painel do algoritmo do pintor marca os pixels que diferem da imagem do z-buffer.</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="97"/>
        <source>Gouraud&apos;s faults: Mach bands, a missed highlight</source>
        <translation>Os defeitos de Gouraud: bandas de Mach, um brilho perdido</translation>
    </message>
    <message>
        <location filename="../app/documents/examples.cpp" line="98"/>
        <source>Left, a coarse sphere in Gouraud shading: the brightness bends at every edge and the eye sees bands there (Mach bands). Right, a square of two triangles whose highlight falls between its corners: Gouraud lights only the corners and misses it. Switch to Phong shading and the highlight appears in the middle of the square.</source>
        <translation>À esquerda, uma esfera grosseira em sombreamento Gouraud: o brilho muda de inclinação em cada aresta e o olho vê faixas ali (bandas de Mach). À direita, um quadrado de dois triângulos cujo brilho cai entre os vértices: Gouraud ilumina só os vértices e o perde. Mude para o sombreamento Phong e o brilho aparece no meio do quadrado.</translation>
    </message>
</context>
<context>
    <name>Messages</name>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="15"/>
        <source>expected the degree %1 of the Bezier surface (an integer from 1 to %2), found %3</source>
        <translation>esperava o grau %1 da superfície de Bézier (um inteiro de 1 a %2), encontrou %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="18"/>
        <source>ignored %1 after the Bezier surface&apos;s two degrees</source>
        <translation>ignorou %1 após os dois graus da superfície de Bézier</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="19"/>
        <source>expected the number of evaluations per direction (an integer from 2 to %1), found %2</source>
        <translation>esperava o número de avaliações por direção (um inteiro de 2 a %1), encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="22"/>
        <source>the header declares a Bezier surface of degrees %1 x %2, so %3 control points (one a line), but only %4</source>
        <translation>o cabeçalho declara uma superfície de Bézier de graus %1 x %2, portanto %3 pontos de controle (um por linha), mas só %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="25"/>
        <source>%1 line follows</source>
        <translation>%1 linha vem a seguir</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="26"/>
        <source>%1 lines follow</source>
        <translation>%1 linhas vêm a seguir</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="27"/>
        <source>control point (%1, %2)</source>
        <translation>ponto de controle (%1, %2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="28"/>
        <source>ignored %1 after the %2 control points of the Bezier surface</source>
        <translation>ignorou %1 após os %2 pontos de controle da superfície de Bézier</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="30"/>
        <source>the header &apos;vertices triangles&apos; (two integers)</source>
        <translation>o cabeçalho &apos;vértices triângulos&apos; (dois inteiros)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="31"/>
        <source>expected %1, found the end of the file</source>
        <translation>esperava %1, encontrou o fim do arquivo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="32"/>
        <source>this is an original Movie.BYU file (header &apos;parts vertices polygons edges&apos;), not the course&apos;s .byu format (header &apos;vertices triangles&apos;)</source>
        <translation>este é um arquivo Movie.BYU original (cabeçalho &apos;partes vértices polígonos arestas&apos;), não o formato .byu do curso (cabeçalho &apos;vértices triângulos&apos;)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="35"/>
        <source>vertices</source>
        <translation>vértices</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="36"/>
        <source>expected the number of triangles after the number of vertices, found the end of the line</source>
        <translation>esperava o número de triângulos após o número de vértices, encontrou o fim da linha</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="39"/>
        <source>triangles</source>
        <translation>triângulos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="40"/>
        <source>ignored %1 after the header&apos;s two counts</source>
        <translation>ignorou %1 após as duas contagens do cabeçalho</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="41"/>
        <source>this looks like a course Bezier surface (degrees %1 x %2, %3 evaluations per direction), not a triangle mesh</source>
        <translation>isto parece uma superfície de Bézier do curso (graus %1 x %2, %3 avaliações por direção), não uma malha de triângulos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="44"/>
        <source>the header declares %1 and %2 (%3), but only %4</source>
        <translation>o cabeçalho declara %1 e %2 (%3), mas só %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="45"/>
        <source>%1 line</source>
        <translation>%1 linha</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="46"/>
        <source>%1 lines</source>
        <translation>%1 linhas</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="47"/>
        <source>vertex %1 of %2</source>
        <translation>vértice %1 de %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="48"/>
        <source>triangle %1 of %2 (three vertex indices)</source>
        <translation>triângulo %1 de %2 (três índices de vértice)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="49"/>
        <source>expected 3 vertex indices for triangle %1 of %2, found %3</source>
        <translation>esperava 3 índices de vértice para o triângulo %1 de %2, encontrou %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="50"/>
        <source>polygon %1 has %2 vertex indices, but only triangles (3 indices) are supported</source>
        <translation>o polígono %1 tem %2 índices de vértice, mas só triângulos (3 índices) são aceitos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="53"/>
        <source>expected a vertex index (a positive integer) for triangle %1, found %2</source>
        <translation>esperava um índice de vértice (um inteiro positivo) para o triângulo %1, encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="55"/>
        <source>triangle %1 refers to vertex %2, but indices are 1-based (1 to %3)</source>
        <translation>o triângulo %1 se refere ao vértice %2, mas os índices começam em 1 (de 1 a %3)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="57"/>
        <source>triangle %1 refers to vertex %2, but the file declares only %3</source>
        <translation>o triângulo %1 se refere ao vértice %2, mas o arquivo declara só %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="58"/>
        <source>ignored %1 after the declared %2 and %3 (the header&apos;s counts may be wrong, or a second object follows)</source>
        <translation>ignorou %1 após os %2 e %3 declarados (as contagens do cabeçalho podem estar erradas, ou um segundo objeto vem a seguir)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="62"/>
        <source>the camera position</source>
        <translation>a posição da câmera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="63"/>
        <source>the view direction</source>
        <translation>a direção de visão</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="64"/>
        <source>the up vector</source>
        <translation>o vetor para cima</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="65"/>
        <source>the projection distance and half-sizes</source>
        <translation>a distância de projeção e as metades da largura e da altura da janela</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="66"/>
        <source>the projection distance</source>
        <translation>a distância de projeção</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="67"/>
        <source>the horizontal half-size of the window</source>
        <translation>a metade da largura da janela</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="68"/>
        <source>the vertical half-size of the window</source>
        <translation>a metade da altura da janela</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="69"/>
        <source>the half-sizes of the window</source>
        <translation>as metades da largura e da altura da janela</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="70"/>
        <source>the light position</source>
        <translation>a posição da luz</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="71"/>
        <source>the ambient coefficient</source>
        <translation>o coeficiente ambiente</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="72"/>
        <source>the ambient light colour</source>
        <translation>a cor da luz ambiente</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="73"/>
        <source>the diffuse coefficient</source>
        <translation>o coeficiente difuso</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="74"/>
        <source>the diffuse colour of the object</source>
        <translation>a cor difusa do objeto</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="75"/>
        <source>the specular coefficient</source>
        <translation>o coeficiente especular</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="76"/>
        <source>the light colour</source>
        <translation>a cor da luz</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="77"/>
        <source>the specular exponent</source>
        <translation>o expoente especular</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="78"/>
        <source>the number of lights</source>
        <translation>o número de luzes</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="79"/>
        <source>the diffuse coefficient of each channel</source>
        <translation>o coeficiente difuso de cada canal</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="80"/>
        <source>the camera&apos;s %1</source>
        <translation>a câmera (%1)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="81"/>
        <source>the lighting&apos;s %1</source>
        <translation>a iluminação (%1)</translation>
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
        <translation>detectado pelo arquivo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="87"/>
        <source>UFPE (Pl; ka; Ia; kd; Od; ks; Il; n)</source>
        <translation>UFPE (Pl; ka; Ia; kd; Od; ks; Il; n)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="88"/>
        <source>UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; Il)</source>
        <translation>UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L vezes Pl; Il)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="89"/>
        <source>UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)</source>
        <translation>UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="90"/>
        <source>a UFPE camera, C; N; V; d hx hy</source>
        <translation>uma câmera UFPE, C; N; V; d hx hy</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="91"/>
        <source>a UFRPE camera, N; V; d; hx; hy; C</source>
        <translation>uma câmera UFRPE, N; V; d; hx; hy; C</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="92"/>
        <source>a UFRPE camera, C; N; V; hx hy; d</source>
        <translation>uma câmera UFRPE, C; N; V; hx hy; d</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="93"/>
        <source>a key = value camera</source>
        <translation>uma câmera key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="94"/>
        <source>a camera</source>
        <translation>uma câmera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="95"/>
        <source>a UFPE lighting file, Pl; ka; Ia; kd; Od; ks; Il; n</source>
        <translation>um arquivo de iluminação UFPE, Pl; ka; Ia; kd; Od; ks; Il; n</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="96"/>
        <source>a UFPE multi-light lighting file, ka; Ia; kd; Od; ks; n; L; L times Pl; Il</source>
        <translation>um arquivo de iluminação UFPE multi-light, ka; Ia; kd; Od; ks; n; L; L vezes Pl; Il</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="98"/>
        <source>a UFRPE lighting file, Iamb; Ka; Il; Pl; Kd; Od; Ks; n</source>
        <translation>um arquivo de iluminação UFRPE, Iamb; Ka; Il; Pl; Kd; Od; Ks; n</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="99"/>
        <source>a key = value lighting file</source>
        <translation>um arquivo de iluminação key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="100"/>
        <source>a lighting file</source>
        <translation>um arquivo de iluminação</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="101"/>
        <source>the 1 line has %1</source>
        <translation>a única linha tem %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="102"/>
        <source>the %1 lines have %2 numbers</source>
        <translation>as %1 linhas têm %2 números</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="103"/>
        <source>line %1 has %2 where %3 needs %4</source>
        <translation>a linha %1 tem %2 onde %3 precisa de %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="104"/>
        <source>its last line, %1, is missing</source>
        <translation>falta a sua última linha, %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="105"/>
        <source>line %1 is one line more</source>
        <translation>a linha %1 é uma linha a mais</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="106"/>
        <source>no line contains &apos;=&apos; and %1</source>
        <translation>nenhuma linha contém &apos;=&apos; e %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="107"/>
        <source>%1: its first %2 lines fit this layout, and the rest is left over</source>
        <translation>%1: as suas primeiras %2 linhas se encaixam neste formato, e o resto sobra</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="109"/>
        <source>%1, as in that layout</source>
        <translation>%1, como nesse formato</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="110"/>
        <source>%1: no layout fits exactly, and this one is one line away (%2)</source>
        <translation>%1: nenhum formato se encaixa exatamente, e este fica a uma linha de distância (%2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="111"/>
        <source>one line away from %1</source>
        <translation>a uma linha de distância de %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="112"/>
        <source>an empty file</source>
        <translation>um arquivo vazio</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="113"/>
        <source>only blank lines</source>
        <translation>só linhas em branco</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="114"/>
        <source>1 line with %1</source>
        <translation>1 linha com %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="115"/>
        <source>%1 lines with %2 numbers</source>
        <translation>%1 linhas com %2 números</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="116"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="117"/>
        <source>lines contain &apos;=&apos;</source>
        <translation>há linhas com &apos;=&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="118"/>
        <source>expected %1 or key = value, found %2 (if the layout is known, choose it by hand: --camera-format / --lighting-format, or File &gt; Course File Layouts)</source>
        <translation>esperava %1 ou key = value, encontrou %2 (se o formato é conhecido, escolha-o à mão: --camera-format / --lighting-format, ou Arquivo &gt; Formatos dos arquivos do curso)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="122"/>
        <source>a camera in one of the layouts UFPE (C; N; V; d hx hy), UFRPE (N; V; d; hx; hy; C), UFRPE (C; N; V; hx hy; d)</source>
        <translation>uma câmera num dos formatos UFPE (C; N; V; d hx hy), UFRPE (N; V; d; hx; hy; C), UFRPE (C; N; V; hx hy; d)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="125"/>
        <source>lighting in one of the layouts UFPE (Pl; ka; Ia; kd; Od; ks; Il; n), UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; Il), UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)</source>
        <translation>uma iluminação num dos formatos UFPE (Pl; ka; Ia; kd; Od; ks; Il; n), UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L vezes Pl; Il), UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="129"/>
        <source>expected the number of lights L (a positive whole number), found %1</source>
        <translation>esperava o número de luzes L (um número inteiro positivo), encontrou %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="131"/>
        <source>L = %1 lights need twice as many lines after it (Pl and Il for each), but only %2</source>
        <translation>L = %1 luzes precisam do dobro de linhas depois dele (Pl e Il para cada uma), mas só %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="134"/>
        <source>L = %1 lights need %2 lines after it (Pl and Il for each), but only %3</source>
        <translation>L = %1 luzes precisam de %2 linhas depois dele (Pl e Il para cada uma), mas só %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="136"/>
        <source>%1; the layout was set to %2</source>
        <translation>%1; o formato foi definido como %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="137"/>
        <source>%1; the layout was set to %2, but the file looks like %3 (%4)</source>
        <translation>%1; o formato foi definido como %2, mas o arquivo parece %3 (%4)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="138"/>
        <source>the layout was chosen, not detected</source>
        <translation>o formato foi escolhido, não detectado</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="139"/>
        <source>read as %1 (%2)</source>
        <translation>lido como %1 (%2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="141"/>
        <source>%1 or %2 numbers</source>
        <translation>%1 ou %2 números</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="142"/>
        <source>%1 value</source>
        <translation>%1 valor</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="143"/>
        <source>%1 values</source>
        <translation>%1 valores</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="144"/>
        <source>%1 vertex</source>
        <translation>%1 vértice</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="145"/>
        <source>%1 vertices</source>
        <translation>%1 vértices</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="146"/>
        <source>%1 triangle</source>
        <translation>%1 triângulo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="147"/>
        <source>%1 triangles</source>
        <translation>%1 triângulos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="148"/>
        <source>%1 number</source>
        <translation>%1 número</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="149"/>
        <source>%1 numbers</source>
        <translation>%1 números</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="150"/>
        <source>%1 of light %2</source>
        <translation>%1 da luz %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="151"/>
        <source>found %1 (separate the values with spaces, not commas)</source>
        <translation>encontrou %1 (separe os valores com espaços, não com vírgulas)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="152"/>
        <source>found %1 (the decimal separator is &apos;.&apos;)</source>
        <translation>encontrou %1 (o separador decimal é &apos;.&apos;)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="153"/>
        <source>found %1, which is out of range</source>
        <translation>encontrou %1, que está fora do intervalo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="154"/>
        <source>found %1, which is not a finite number</source>
        <translation>encontrou %1, que não é um número finito</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="155"/>
        <source>found %1</source>
        <translation>encontrou %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="156"/>
        <source>%1 and %2</source>
        <translation>%1 e %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="157"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="158"/>
        <source>expected %1, %2 (%3), found the end of the file</source>
        <translation>esperava %1, %2 (%3), encontrou o fim do arquivo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="159"/>
        <source>expected a number for %1, %2</source>
        <translation>esperava um número para %1, %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="160"/>
        <source>expected %1 for %2, found %3</source>
        <translation>esperava %1 para %2, encontrou %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="161"/>
        <source>ignored %1 after %2</source>
        <translation>ignorou %1 após %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="162"/>
        <source>%1 = %2 is outside %3, the range the course gives for it</source>
        <translation>%1 = %2 está fora de %3, o intervalo que o curso dá para ele</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="163"/>
        <source>%1 of light %2 = %3 is outside %4, the range the course gives for it</source>
        <translation>%1 da luz %2 = %3 está fora de %4, o intervalo que o curso dá para ele</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="165"/>
        <source>%1 = %2 is not positive: (R.V)^n then makes no highlight (it is 1 everywhere for n = 0 and grows without bound where R.V nears 0 for n &lt; 0, where the specular term is left out)</source>
        <translation>%1 = %2 não é positivo: assim (R.V)^n não faz brilho (vale 1 em todo lugar para n = 0 e cresce sem limite onde R.V se aproxima de 0 para n &lt; 0, caso em que o termo especular é deixado de fora)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="169"/>
        <source>expected the number of %1 (a non-negative integer), found %2</source>
        <translation>esperava o número de %1 (um inteiro não negativo), encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="170"/>
        <source>expected %1, found a comment (%2), but .byu files have no comments</source>
        <translation>esperava %1, encontrou um comentário (%2), mas arquivos .byu não têm comentários</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="172"/>
        <source>expected a number for the %1 coordinate of %2, %3</source>
        <translation>esperava um número para a coordenada %1 do %2, %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="173"/>
        <source>%1 (x y z)</source>
        <translation>%1 (x y z)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="174"/>
        <source>expected 3 coordinates for %1, found %2</source>
        <translation>esperava 3 coordenadas para o %1, encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="175"/>
        <source>ignored extra values at the end of %1 (the first is here)</source>
        <translation>ignorou valores a mais no fim de %1 (o primeiro está aqui)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="176"/>
        <source>%1 vertex of %2 is not used by any triangle</source>
        <translation>%1 vértice de %2 não é usado por nenhum triângulo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="177"/>
        <source>%1 vertices of %2 are not used by any triangle</source>
        <translation>%1 vértices de %2 não são usados por nenhum triângulo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="178"/>
        <source>the object has no triangles</source>
        <translation>o objeto não tem triângulos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="180"/>
        <source>the light position (x y z, or x y z w: w = 0 for a directional light)</source>
        <translation>a posição da luz (x y z, ou x y z w: w = 0 para uma luz direcional)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="182"/>
        <source>the emission of the object</source>
        <translation>a emissão do objeto</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="183"/>
        <source>two-sided lighting, 1 or 0</source>
        <translation>iluminação dos dois lados, 1 ou 0</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="184"/>
        <source>Blinn-Phong highlights, 1 or 0</source>
        <translation>brilhos de Blinn-Phong, 1 ou 0</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="185"/>
        <source>the attenuation kc kl kq</source>
        <translation>a atenuação kc kl kq</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="186"/>
        <source>the spot direction</source>
        <translation>a direção do spot</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="187"/>
        <source>the spot cutoff angle in degrees</source>
        <translation>o ângulo de corte do spot em graus</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="188"/>
        <source>the spot exponent</source>
        <translation>o expoente do spot</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="189"/>
        <source>%1; optionally %2</source>
        <translation>%1; opcionalmente %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="190"/>
        <source>%1; optionally %2; Pl2, Il2 ... for lights 2 to %3</source>
        <translation>%1; opcionalmente %2; Pl2, Il2 ... para as luzes 2 a %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="191"/>
        <source>expected &apos;key = value&apos;, found a line without &apos;=&apos; (%1 ...)</source>
        <translation>esperava &apos;key = value&apos;, encontrou uma linha sem &apos;=&apos; (%1 ...)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="192"/>
        <source>expected &apos;key = value&apos;, found a line without &apos;=&apos; (%1)</source>
        <translation>esperava &apos;key = value&apos;, encontrou uma linha sem &apos;=&apos; (%1)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="193"/>
        <source>expected a key before &apos;=&apos;, found nothing</source>
        <translation>esperava uma chave antes de &apos;=&apos;, não encontrou nada</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="194"/>
        <source>expected one key before &apos;=&apos;, found %1</source>
        <translation>esperava uma chave antes de &apos;=&apos;, encontrou %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="195"/>
        <source>ignored %1: the camera&apos;s axes come from N and V</source>
        <translation>ignorou %1: os eixos da câmera vêm de N e V</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="196"/>
        <source>ignored the unknown key %1 (a camera has %2; a lighting file has %3)</source>
        <translation>ignorou a chave desconhecida %1 (uma câmera tem %2; um arquivo de iluminação tem %3)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="198"/>
        <source>ignored the unknown key %1 (a lighting file has %2; a camera has %3)</source>
        <translation>ignorou a chave desconhecida %1 (um arquivo de iluminação tem %2; uma câmera tem %3)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="200"/>
        <source>expected %1 for %2, found none</source>
        <translation>esperava %1 para %2, não encontrou nenhum</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="201"/>
        <source>expected the camera keys %1, found none of them (only lighting file keys)</source>
        <translation>esperava as chaves de câmera %1, não encontrou nenhuma delas (só chaves de arquivo de iluminação)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="203"/>
        <source>expected the camera keys %1, found none of them</source>
        <translation>esperava as chaves de câmera %1, não encontrou nenhuma delas</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="204"/>
        <source>expected the lighting file keys %1, found none of them (only camera keys)</source>
        <translation>esperava as chaves de arquivo de iluminação %1, não encontrou nenhuma delas (só chaves de câmera)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="206"/>
        <source>expected the lighting file keys %1, found none of them</source>
        <translation>esperava as chaves de arquivo de iluminação %1, não encontrou nenhuma delas</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="207"/>
        <source>expected a line &apos;%1 = ...&apos; (%2, %3), found no %1</source>
        <translation>esperava uma linha &apos;%1 = ...&apos; (%2, %3), não encontrou %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="208"/>
        <source>expected lines for %1 (a camera needs %2), found none</source>
        <translation>esperava linhas para %1 (uma câmera precisa de %2), não encontrou nenhuma</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="209"/>
        <source>expected lines for %1 (a lighting file needs %2), found none</source>
        <translation>esperava linhas para %1 (um arquivo de iluminação precisa de %2), não encontrou nenhuma</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="210"/>
        <source>expected each key once, found %1 again (first given on line %2)</source>
        <translation>esperava cada chave uma só vez, encontrou %1 de novo (dada primeiro na linha %2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="212"/>
        <source>expected light %1 (%2, %3) before light %4, found %5 (lights are numbered without gaps)</source>
        <translation>esperava a luz %1 (%2, %3) antes da luz %4, encontrou %5 (as luzes são numeradas sem lacunas)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="215"/>
        <source>expected a line &apos;%1 = ...&apos; (%2 of light %3), found %4 without it</source>
        <translation>esperava uma linha &apos;%1 = ...&apos; (%2 da luz %3), encontrou %4 sem ela</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="217"/>
        <source>expected 1 or 0 for %1, found %2</source>
        <translation>esperava 1 ou 0 para %1, encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="218"/>
        <source>expected %1 coefficients of 0 or more (kc kl kq), found %2</source>
        <translation>esperava em %1 coeficientes de 0 ou mais (kc kl kq), encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="219"/>
        <source>expected %1 with a coefficient above 0, found 0 0 0 (1 / 0 light)</source>
        <translation>esperava %1 com um coeficiente acima de 0, encontrou 0 0 0 (luz 1 / 0)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="221"/>
        <source>%1 has no effect: a directional light (w = 0) is not attenuated</source>
        <translation>%1 não tem efeito: uma luz direcional (w = 0) não é atenuada</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="223"/>
        <source>expected a spot direction other than 0 0 0 for %1</source>
        <translation>esperava uma direção do spot diferente de 0 0 0 para %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="224"/>
        <source>expected %1 from 0 to 90 degrees, or 180 (not a spot), found %2</source>
        <translation>esperava %1 de 0 a 90 graus, ou 180 (não é spot), encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="226"/>
        <source>%1: no %2, the spot points along -z (OpenGL&apos;s default)</source>
        <translation>%1: sem %2, o spot aponta ao longo de -z (o padrão do OpenGL)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="227"/>
        <source>expected %1 from 0 to 128, found %2</source>
        <translation>esperava %1 de 0 a 128, encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="228"/>
        <source>light %1 is not a spot without %2 (0 to 90 degrees): its spot direction and exponent are unused</source>
        <translation>a luz %1 não é um spot sem %2 (0 a 90 graus): a direção e o expoente do spot dela não são usados</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="232"/>
        <source>read as an original Movie.BYU file (the header has four integers: parts, vertices, polygons, edges): %1, fan-triangulated into %2</source>
        <translation>lido como um arquivo Movie.BYU original (o cabeçalho tem quatro inteiros: partes, vértices, polígonos, arestas): %1, triangulados em leque em %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="235"/>
        <source>read as a course Bezier surface (the header &apos;m n&apos; is followed by a line of one number, the evaluations per direction): degrees %1 x %2, evaluated on a %3 x %3 grid into %4 and %5</source>
        <translation>lido como uma superfície de Bézier do curso (o cabeçalho &apos;m n&apos; é seguido de uma linha com um número, as avaliações por direção): graus %1 x %2, avaliada numa grade de %3 x %3 em %4 e %5</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="240"/>
        <source>cannot write the camera: its values must be finite numbers (a course file cannot hold nan or inf)</source>
        <translation>não é possível gravar a câmera: seus valores devem ser números finitos (um arquivo do curso não comporta nan nem inf)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="243"/>
        <source>cannot write a camera in the layout &apos;auto&apos;: choose UFPE, UFRPE or key = value</source>
        <translation>não é possível gravar uma câmera no formato &apos;auto&apos;: escolha UFPE, UFRPE ou key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="246"/>
        <source>an emission (Ke)</source>
        <translation>uma emissão (Ke)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="247"/>
        <source>one-sided lighting</source>
        <translation>iluminação de um lado só</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="248"/>
        <source>Blinn-Phong highlights</source>
        <translation>brilhos de Blinn-Phong</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="249"/>
        <source>a directional light (w = 0)</source>
        <translation>uma luz direcional (w = 0)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="250"/>
        <source>an attenuated light</source>
        <translation>uma luz atenuada</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="251"/>
        <source>a spot light</source>
        <translation>um spot</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="252"/>
        <source>cannot write lighting in the layout &apos;auto&apos;: choose UFPE, UFPE multi-light, UFRPE or key = value</source>
        <translation>não é possível gravar a iluminação no formato &apos;auto&apos;: escolha UFPE, UFPE multi-light, UFRPE ou key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="255"/>
        <source>cannot write %1 light in the layout %2, which holds exactly one: choose the UFPE multi-light layout or key = value</source>
        <translation>não é possível gravar %1 luz no formato %2, que comporta exatamente uma: escolha o formato UFPE multi-light ou key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="258"/>
        <source>cannot write %1 lights in the layout %2, which holds exactly one: choose the UFPE multi-light layout or key = value</source>
        <translation>não é possível gravar %1 luzes no formato %2, que comporta exatamente uma: escolha o formato UFPE multi-light ou key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="261"/>
        <source>cannot write lighting without lights: the UFPE multi-light and key = value layouts hold one light or more</source>
        <translation>não é possível gravar uma iluminação sem luzes: os formatos UFPE multi-light e key = value comportam uma luz ou mais</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="264"/>
        <source>cannot write %1 lights in a key = value file, which holds %2 at most (Pl to %3)</source>
        <translation>não é possível gravar %1 luzes num arquivo key = value, que comporta no máximo %2 (Pl a %3)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="267"/>
        <source>cannot write %1 in the layout %2, which holds the course&apos;s point lights only: choose key = value</source>
        <translation>não é possível gravar %1 no formato %2, que só comporta as luzes pontuais do curso: escolha key = value</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="270"/>
        <source>cannot write the lighting: its values must be finite numbers (a course file cannot hold nan or inf)</source>
        <translation>não é possível gravar a iluminação: seus valores devem ser números finitos (um arquivo do curso não comporta nan nem inf)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="273"/>
        <source>cannot write lighting in the layout &apos;auto&apos;</source>
        <translation>não é possível gravar a iluminação no formato &apos;auto&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="275"/>
        <source>%1 argument</source>
        <translation>%1 argumento</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="276"/>
        <source>%1 arguments</source>
        <translation>%1 argumentos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="277"/>
        <source>skipped %1 line with the unknown command &apos;%2&apos;</source>
        <translation>pulou %1 linha com o comando desconhecido &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="278"/>
        <source>skipped %1 lines with the unknown command &apos;%2&apos;</source>
        <translation>pulou %1 linhas com o comando desconhecido &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="279"/>
        <source>expected a &apos;png width height file&apos; command, found none</source>
        <translation>esperava um comando &apos;png width height file&apos;, não encontrou nenhum</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="280"/>
        <source>expected %1 number after &apos;%2&apos; (%3), found %4</source>
        <translation>esperava %1 número após &apos;%2&apos; (%3), encontrou %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="281"/>
        <source>expected %1 numbers after &apos;%2&apos; (%3), found %4</source>
        <translation>esperava %1 números após &apos;%2&apos; (%3), encontrou %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="282"/>
        <source>expected a number in &apos;%1&apos; (%2), found %3</source>
        <translation>esperava um número em &apos;%1&apos; (%2), encontrou %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="283"/>
        <source>ignored %1 value after &apos;%2&apos;</source>
        <translation>ignorou %1 valor após &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="284"/>
        <source>ignored %1 values after &apos;%2&apos;</source>
        <translation>ignorou %1 valores após &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="285"/>
        <source>expected a vertex index in &apos;%1&apos;, found %2</source>
        <translation>esperava um índice de vértice em &apos;%1&apos;, encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="286"/>
        <source>&apos;%1&apos; refers to vertex %2, but indices start at 1 (or count back from -1, the last)</source>
        <translation>&apos;%1&apos; se refere ao vértice %2, mas os índices começam em 1 (ou contam de trás para a frente a partir de -1, o último)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="289"/>
        <source>&apos;%2&apos; refers to vertex %3, but only %1 vertex is defined so far</source>
        <translation>&apos;%2&apos; se refere ao vértice %3, mas só %1 vértice foi definido até aqui</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="290"/>
        <source>&apos;%2&apos; refers to vertex %3, but only %1 vertices are defined so far</source>
        <translation>&apos;%2&apos; se refere ao vértice %3, mas só %1 vértices foram definidos até aqui</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="292"/>
        <source>expected %1 vertex index in &apos;%2&apos; (%3), found %4</source>
        <translation>esperava %1 índice de vértice em &apos;%2&apos; (%3), encontrou %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="293"/>
        <source>expected %1 vertex indices in &apos;%2&apos; (%3), found %4</source>
        <translation>esperava %1 índices de vértice em &apos;%2&apos; (%3), encontrou %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="294"/>
        <source>expected the number of subdivisions after &apos;%1&apos;, found the end of the line</source>
        <translation>esperava o número de subdivisões após &apos;%1&apos;, encontrou o fim da linha</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="296"/>
        <source>expected the number of subdivisions (a whole number from 1 to 10) after &apos;%1&apos;, found %2</source>
        <translation>esperava o número de subdivisões (um número inteiro de 1 a 10) após &apos;%1&apos;, encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="299"/>
        <source>expected a &apos;png width height file&apos; command before &apos;%1&apos;</source>
        <translation>esperava um comando &apos;png width height file&apos; antes de &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="300"/>
        <source>this command would bring the file to %1 triangles, more than the limit of %2 a command file may draw</source>
        <translation>este comando levaria o arquivo a %1 triângulos, mais que o limite de %2 que um arquivo de comandos pode desenhar</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="303"/>
        <source>expected &apos;png width height file&apos;, found %1</source>
        <translation>esperava &apos;png width height file&apos;, encontrou %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="304"/>
        <source>expected the image width (a whole number from 1 to 65536), found %1</source>
        <translation>esperava a largura da imagem (um número inteiro de 1 a 65536), encontrou %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="306"/>
        <source>expected the image height (a whole number from 1 to 65536), found %1</source>
        <translation>esperava a altura da imagem (um número inteiro de 1 a 65536), encontrou %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="308"/>
        <source>expected an image file name after &apos;png width height&apos;, found %1</source>
        <translation>esperava um nome de arquivo de imagem após &apos;png width height&apos;, encontrou %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="309"/>
        <source>the image name %1 reaches into folders: it is written as %2 in the output folder</source>
        <translation>o nome de imagem %1 entra em pastas: ela é gravada como %2 na pasta de saída</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="312"/>
        <source>an earlier png command (line %1) names %2 too: this image replaces it</source>
        <translation>um comando png anterior (linha %1) também nomeia %2: esta imagem a substitui</translation>
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
        <translation>&apos;trit&apos; precisa de uma textura: esperava um comando &apos;texture file.png&apos; antes dele</translation>
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
        <translation>a11 a12 ... a44, linha por linha</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="324"/>
        <source>l r b t n f</source>
        <translation>l r b t n f</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="325"/>
        <source>&apos;%1&apos; needs l != r, b != t and n != f, found %2 %3 %4 %5 %6 %7</source>
        <translation>&apos;%1&apos; precisa de l != r, b != t e n != f, encontrou %2 %3 %4 %5 %6 %7</translation>
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
        <translation>graus</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="329"/>
        <source>degrees x y z</source>
        <translation>graus x y z</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="330"/>
        <source>&apos;rotate&apos; needs an axis, found the zero vector</source>
        <translation>&apos;rotate&apos; precisa de um eixo, encontrou o vetor nulo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="331"/>
        <source>eye center upx upy upz</source>
        <translation>eye center upx upy upz</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="332"/>
        <source>expected &apos;lookat eye center upx upy upz&apos;, found %1</source>
        <translation>esperava &apos;lookat eye center upx upy upz&apos;, encontrou %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="333"/>
        <source>expected a number in &apos;lookat&apos; (eye center upx upy upz), found %1</source>
        <translation>esperava um número em &apos;lookat&apos; (eye center upx upy upz), encontrou %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="335"/>
        <source>&apos;lookat&apos; needs an eye apart from the center and an up that is not along the line of sight</source>
        <translation>&apos;lookat&apos; precisa de um olho afastado do centro e de um vetor para cima que não esteja ao longo da linha de visão</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="338"/>
        <source>p1 p2 p3 p4</source>
        <translation>p1 p2 p3 p4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="339"/>
        <source>expected a file name after &apos;texture&apos;, found the end of the line</source>
        <translation>esperava um nome de arquivo após &apos;texture&apos;, encontrou o fim da linha</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="341"/>
        <source>lx ly lz</source>
        <translation>lx ly lz</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="342"/>
        <source>&apos;sunlight&apos; needs a direction, found the zero vector</source>
        <translation>&apos;sunlight&apos; precisa de uma direção, encontrou o vetor nulo</translation>
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
        <translation>partes</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="347"/>
        <source>polygons</source>
        <translation>polígonos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="348"/>
        <source>polygon indices (edges)</source>
        <translation>índices de polígono (arestas)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="349"/>
        <source>%1 part</source>
        <translation>%1 parte</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="350"/>
        <source>%1 parts</source>
        <translation>%1 partes</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="351"/>
        <source>%1 polygon</source>
        <translation>%1 polígono</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="352"/>
        <source>%1 polygons</source>
        <translation>%1 polígonos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="353"/>
        <source>%1 polygon index</source>
        <translation>%1 índice de polígono</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="354"/>
        <source>%1 polygon indices</source>
        <translation>%1 índices de polígono</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="355"/>
        <source>%1, %2 and %3</source>
        <translation>%1, %2 e %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="356"/>
        <source>the header declares %1 (%2: 2 a part, 3 a vertex, 1 an index), but only %3</source>
        <translation>o cabeçalho declara %1 (%2: 2 por parte, 3 por vértice, 1 por índice), mas só %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="358"/>
        <source>more numbers than a file can hold</source>
        <translation>mais números do que um arquivo pode conter</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="359"/>
        <source>%1 number follows</source>
        <translation>%1 número vem a seguir</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="360"/>
        <source>%1 numbers follow</source>
        <translation>%1 números vêm a seguir</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="361"/>
        <source>the header declares %1 but only %2, fewer than the 3 each polygon needs</source>
        <translation>o cabeçalho declara %1, mas só %2, menos que os 3 de que cada polígono precisa</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="363"/>
        <source>the first polygon of part %1</source>
        <translation>o primeiro polígono da parte %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="364"/>
        <source>the last polygon of part %1</source>
        <translation>o último polígono da parte %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="365"/>
        <source>expected %1 (a positive integer), found %2</source>
        <translation>esperava %1 (um inteiro positivo), encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="366"/>
        <source>expected the polygon range of part %1 within 1 to %2, first &lt;= last, found %3 to %4</source>
        <translation>esperava o intervalo de polígonos da parte %1 dentro de 1 a %2, primeiro &lt;= último, encontrou %3 a %4</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="369"/>
        <source>an index of polygon %1</source>
        <translation>um índice do polígono %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="370"/>
        <source>expected a vertex index (a non-zero integer, negated at the end of a polygon) for polygon %1, found %2</source>
        <translation>esperava um índice de vértice (um inteiro diferente de zero, negativo no fim de um polígono) para o polígono %1, encontrou %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="373"/>
        <source>polygon %1 starts here, but the header declares only %2</source>
        <translation>o polígono %1 começa aqui, mas o cabeçalho declara só %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="374"/>
        <source>polygon %1 refers to vertex 0, but indices are 1-based (1 to %2)</source>
        <translation>o polígono %1 se refere ao vértice 0, mas os índices começam em 1 (de 1 a %2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="376"/>
        <source>polygon %1 refers to vertex %2, but the file declares only %3</source>
        <translation>o polígono %1 se refere ao vértice %2, mas o arquivo declara só %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="377"/>
        <source>polygon %1 has %2, but a polygon needs at least 3</source>
        <translation>o polígono %1 tem %2, mas um polígono precisa de pelo menos 3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="378"/>
        <source>expected the last index of polygon %1 to be negative (it ends the polygon), found the end of the header&apos;s %2</source>
        <translation>esperava que o último índice do polígono %1 fosse negativo (ele termina o polígono), encontrou o fim dos %2 do cabeçalho</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="381"/>
        <source>the header declares %1, but its %2 end only %3</source>
        <translation>o cabeçalho declara %1, mas os seus %2 terminam só %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="382"/>
        <source>ignored %1 after the declared %2 (the header&apos;s counts may be wrong, or a second object follows)</source>
        <translation>ignorou %1 após os %2 declarados (as contagens do cabeçalho podem estar erradas, ou um segundo objeto vem a seguir)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="386"/>
        <source>the camera&apos;s C, N and V must be finite numbers</source>
        <translation>C, N e V da câmera devem ser números finitos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="387"/>
        <source>N, the view direction, is the zero vector: it must point from the camera toward the scene</source>
        <translation>N, a direção de visão, é o vetor nulo: ele deve apontar da câmera para a cena</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="390"/>
        <source>V, the up vector, is the zero vector: it must say which way is up</source>
        <translation>V, o vetor para cima, é o vetor nulo: ele deve dizer para que lado fica o alto</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="392"/>
        <source>d, the distance to the projection plane, is 0: the projection (d/hx) x/z would squash every point to the centre</source>
        <translation>d, a distância ao plano de projeção, é 0: a projeção (d/hx) x/z esmagaria todo ponto no centro</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="395"/>
        <source>hx, the horizontal half-size of the window, is 0: the projection (d/hx) x/z divides by it</source>
        <translation>hx, a metade da largura da janela, é 0: a projeção (d/hx) x/z divide por ele</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="398"/>
        <source>hy, the vertical half-size of the window, is 0: the projection (d/hy) y/z divides by it</source>
        <translation>hy, a metade da altura da janela, é 0: a projeção (d/hy) y/z divide por ele</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="401"/>
        <source>V %1 is parallel to N %2: Gram-Schmidt leaves nothing of V, so &apos;up&apos; is undefined; choose a V that is not along N</source>
        <translation>V %1 é paralelo a N %2: Gram-Schmidt não deixa nada de V, então o &quot;para cima&quot; fica indefinido; escolha um V que não esteja ao longo de N</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="404"/>
        <source>hx is negative: the image is mirrored left to right</source>
        <translation>hx é negativo: a imagem é espelhada da esquerda para a direita</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="405"/>
        <source>hy is negative: the image is mirrored top to bottom</source>
        <translation>hy é negativo: a imagem é espelhada de cima para baixo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="406"/>
        <source>d is negative: the image is turned upside down and mirrored</source>
        <translation>d é negativo: a imagem fica de cabeça para baixo e espelhada</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="408"/>
        <source>the near plane z = %1 and the clip planes</source>
        <translation>o plano próximo z = %1 e os planos de recorte</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="409"/>
        <source>the near plane z = %1</source>
        <translation>o plano próximo z = %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="410"/>
        <source>%1 lies wholly behind the near plane</source>
        <translation>%1 inteiramente atrás do plano próximo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="411"/>
        <source>%1 lie wholly behind the near plane</source>
        <translation>%1 inteiramente atrás do plano próximo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="412"/>
        <source>%1 and %2 wholly outside a clip plane</source>
        <translation>%1 e %2 inteiramente fora de um plano de recorte</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="413"/>
        <source>the clip planes or the guard band 2^28 pixels around the image</source>
        <translation>os planos de recorte ou a banda de guarda de 2^28 pixels em torno da imagem</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="414"/>
        <source>the guard band 2^28 pixels around the image</source>
        <translation>a banda de guarda de 2^28 pixels em torno da imagem</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="415"/>
        <source>%1 lie wholly outside a clip plane</source>
        <translation>%1 inteiramente fora de um plano de recorte</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="416"/>
        <source>%1 triangle was clipped against %2</source>
        <translation>%1 triângulo foi recortado contra %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="417"/>
        <source>%1 triangles were clipped against %2</source>
        <translation>%1 triângulos foram recortados contra %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="418"/>
        <source>%1; %2, not drawn</source>
        <translation>%1; não desenhados: %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="419"/>
        <source>every triangle is behind the camera (is N pointing away from the object?): the image is empty</source>
        <translation>todos os triângulos estão atrás da câmera (N aponta para longe do objeto?): a imagem está vazia</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="422"/>
        <source>%1. The plain divide of seed 000, x/z and y/z with z &lt; 0, would draw it: the object&apos;s point reflection through the eye (turned half a turn on the screen), where the z-buffer, keeping the smallest z, keeps the side farthest from the camera</source>
        <translation>%1. A divisão simples da seed 000, x/z e y/z com z &lt; 0, o desenharia: a reflexão do objeto pelo olho (girada meia volta na tela), em que o z-buffer, que guarda o menor z, guarda o lado mais distante da câmera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="427"/>
        <source>%1. The plain divide of seed 000, x/z and y/z with z &lt; 0, would draw all %2 of them: the object&apos;s point reflection through the eye (turned half a turn on the screen), where the z-buffer, keeping the smallest z, keeps the side farthest from the camera</source>
        <translation>%1. A divisão simples da seed 000, x/z e y/z com z &lt; 0, desenharia todos os %2: a reflexão do objeto pelo olho (girada meia volta na tela), em que o z-buffer, que guarda o menor z, guarda o lado mais distante da câmera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="432"/>
        <source>%1. The plain divide of seed 000, x/z and y/z with z &lt; 0, would draw %2 of them: the object&apos;s point reflection through the eye (turned half a turn on the screen), where the z-buffer, keeping the smallest z, keeps the side farthest from the camera</source>
        <translation>%1. A divisão simples da seed 000, x/z e y/z com z &lt; 0, desenharia %2 deles: a reflexão do objeto pelo olho (girada meia volta na tela), em que o z-buffer, que guarda o menor z, guarda o lado mais distante da câmera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="437"/>
        <source>plain divide: %1 triangle reaches from in front of the eye to at or behind it (w of different signs, or 0): divided by w without clipping, it wraps through infinity and is drawn wrong (clipping at the near plane draws its front part)</source>
        <translation>divisão simples: %1 triângulo vai da frente do olho até o olho ou atrás dele (w de sinais diferentes, ou 0): dividido por w sem recorte, ele dá a volta pelo infinito e é desenhado errado (o recorte no plano próximo desenha a sua parte da frente)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="442"/>
        <source>plain divide: %1 triangles reach from in front of the eye to at or behind it (w of different signs, or 0): divided by w without clipping, it wraps through infinity and is drawn wrong (clipping at the near plane draws its front part)</source>
        <translation>divisão simples: %1 triângulos vão da frente do olho até o olho ou atrás dele (w de sinais diferentes, ou 0): divididos por w sem recorte, eles dão a volta pelo infinito e são desenhados errados (o recorte no plano próximo desenha a sua parte da frente)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="447"/>
        <source>%1 vertices project more than 2^28 pixels from the image and were pulled in to that distance: triangles through them may be distorted on screen</source>
        <translation>%1 vértices se projetam a mais de 2^28 pixels da imagem e foram trazidos para essa distância: os triângulos que passam por eles podem ficar distorcidos na tela</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="450"/>
        <source>%1 triangles project to infinite or undefined coordinates and were not drawn</source>
        <translation>%1 triângulos se projetam em coordenadas infinitas ou indefinidas e não foram desenhados</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="453"/>
        <source>%1 triangle faces away from the camera on a closed surface seen from outside: hidden, so not drawn (back-face culling)</source>
        <translation>%1 triângulo está de costas para a câmera numa superfície fechada vista de fora: oculto, portanto não desenhado (eliminação de faces traseiras)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="456"/>
        <source>%1 triangles face away from the camera on a closed surface seen from outside: hidden, so not drawn (back-face culling)</source>
        <translation>%1 triângulos estão de costas para a câmera numa superfície fechada vista de fora: ocultos, portanto não desenhados (eliminação de faces traseiras)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="459"/>
        <source>%1 triangle is clockwise on screen and culled</source>
        <translation>%1 triângulo está no sentido horário na tela e é descartado</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="460"/>
        <source>%1 triangles are clockwise on screen and culled</source>
        <translation>%1 triângulos estão no sentido horário na tela e são descartados</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="461"/>
        <source>%1 triangle reaches from in front of the eye to at or behind it (w of different signs): only the part with w &gt;= %2 is drawn</source>
        <translation>%1 triângulo vai da frente do olho até o olho ou atrás dele (w de sinais diferentes): só a parte com w &gt;= %2 é desenhada</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="464"/>
        <source>%1 triangles reach from in front of the eye to at or behind it (w of different signs): only the part with w &gt;= %2 is drawn</source>
        <translation>%1 triângulos vão da frente do olho até o olho ou atrás dele (w de sinais diferentes): só a parte com w &gt;= %2 é desenhada</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="467"/>
        <source>plain divide: %1 triangle lies wholly behind the eye (w &lt; 0), drawn without clipping as the point reflection through the eye</source>
        <translation>divisão simples: %1 triângulo está inteiramente atrás do olho (w &lt; 0) e é desenhado sem recorte como a reflexão pelo olho</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="470"/>
        <source>plain divide: %1 triangles lie wholly behind the eye (w &lt; 0), drawn without clipping as the point reflection through the eye</source>
        <translation>divisão simples: %1 triângulos estão inteiramente atrás do olho (w &lt; 0) e são desenhados sem recorte como a reflexão pelo olho</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="474"/>
        <source>no scene to render</source>
        <translation>não há cena para renderizar</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="475"/>
        <source>the image size %1x%2 is empty</source>
        <translation>o tamanho de imagem %1x%2 é vazio</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="476"/>
        <source>no triangle covers a pixel: all %1 triangles in front of the camera project outside the image (check N, d, hx and hy)</source>
        <translation>nenhum triângulo cobre um pixel: todos os %1 triângulos à frente da câmera se projetam fora da imagem (verifique N, d, hx e hy)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="479"/>
        <source>%1 triangles have zero area and no normal</source>
        <translation>%1 triângulos têm área zero e nenhuma normal</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="481"/>
        <source>no frame to step through</source>
        <translation>não há quadro para percorrer passo a passo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="482"/>
        <source>stepping keeps at most %1 fragments, and this frame has %2: the final image and the views still work</source>
        <translation>o passo a passo guarda no máximo %1 fragmentos, e este quadro tem %2: a imagem final e as vistas continuam funcionando</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="485"/>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="486"/>
        <source>internal error: the rows hold %1 pixels and the depth test saw %2 fragments</source>
        <translation>erro interno: as linhas contêm %1 pixels e o teste de profundidade viu %2 fragmentos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="490"/>
        <source>light %1 is %2 above triangle %3 of %4, nearer than float can resolve points there (%5): the pixels under it may be lit from the wrong side</source>
        <translation>a luz %1 está %2 acima do triângulo %3 de %4, mais perto do que o float consegue distinguir pontos ali (%5): os pixels abaixo dela podem ser iluminados pelo lado errado</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="494"/>
        <source>measurement cancelled</source>
        <translation>medição cancelada</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="495"/>
        <source>supersampling must be 1 to 16 samples per axis</source>
        <translation>a superamostragem deve ser de 1 a 16 amostras por eixo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="497"/>
        <source>the scene has no light to move</source>
        <translation>a cena não tem luz para mover</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="498"/>
        <source>no triangle is in front of the camera</source>
        <translation>nenhum triângulo está à frente da câmera</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="500"/>
        <source>the exact reference handles course scenes (the course camera, view z as depth, the course&apos;s Phong lighting with the material&apos;s colour); %1</source>
        <translation>a referência exata trata cenas do curso (a câmera do curso, o z de vista como profundidade, a iluminação de Phong do curso com a cor do material); %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="503"/>
        <source>this scene has no course camera</source>
        <translation>esta cena não tem câmera do curso</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="504"/>
        <source>this scene&apos;s depth is NDC z</source>
        <translation>a profundidade desta cena é o z em NDC</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="505"/>
        <source>%1 has its own projection matrix</source>
        <translation>%1 tem a sua própria matriz de projeção</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="506"/>
        <source>%1 is not lit by the course&apos;s Phong model</source>
        <translation>%1 não é iluminado pelo modelo de Phong do curso</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="507"/>
        <source>%1 takes its colour from its vertices or a texture</source>
        <translation>%1 tira a sua cor dos vértices ou de uma textura</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="508"/>
        <source>%1 is lit with flat normals</source>
        <translation>%1 é iluminado com normais planas</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="509"/>
        <source>samples per axis must be 1 to 16</source>
        <translation>as amostras por eixo devem ser de 1 a 16</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="511"/>
        <source>(%1, %2, %3, %4)</source>
        <translation>(%1, %2, %3, %4)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="512"/>
        <source>the ambient term multiplied by the object colour: Ia*ka*Od instead of Ia*ka</source>
        <translation>o termo ambiente multiplicado pela cor do objeto: Ia*ka*Od em vez de Ia*ka</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="515"/>
        <source>the normal not turned toward the viewer where V.N &lt; 0</source>
        <translation>a normal não virada para o observador onde V.N &lt; 0</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="516"/>
        <source>specular added where R.V &lt; 0 (no check before (R.V)^n)</source>
        <translation>especular somado onde R.V &lt; 0 (sem teste antes de (R.V)^n)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="517"/>
        <source>diffuse and specular computed where N.L &lt; 0 (the light is behind the surface)</source>
        <translation>termos difuso e especular calculados onde N.L &lt; 0 (a luz está atrás da superfície)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="520"/>
        <source>the interpolated normal not normalised</source>
        <translation>a normal interpolada não normalizada</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="521"/>
        <source>%1 shading where another model was asked</source>
        <translation>sombreamento %1 onde outro modelo foi pedido</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="522"/>
        <source>%1 shading where %2 was asked</source>
        <translation>sombreamento %1 onde %2 foi pedido</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="523"/>
        <source>the image mirrored left-right (x runs the other way)</source>
        <translation>a imagem espelhada da esquerda para a direita (x corre ao contrário)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="524"/>
        <source>the image upside down (row 0 at the bottom: y not flipped)</source>
        <translation>a imagem de cabeça para baixo (linha 0 embaixo: y não invertido)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="525"/>
        <source>the image shifted by one pixel: (%1, %2)</source>
        <translation>a imagem deslocada de um pixel: (%1, %2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="526"/>
        <source>%1; pixels covered by one side only: %2 as ours is, %3 with ours carried by the map</source>
        <translation>%1; pixels cobertos por um lado só: %2 com a nossa como está, %3 com a nossa levada pelo mapa</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="527"/>
        <source>check the screen formulas, x = (x_ndc + 1) * width / 2 and y = (1 - y_ndc) * height / 2, each with its own size, and that pixel (x, y) is written at column x of row y</source>
        <translation>verifique as fórmulas da tela, x = (x_ndc + 1) * largura / 2 e y = (1 - y_ndc) * altura / 2, cada uma com o seu tamanho, e que o pixel (x, y) é escrito na coluna x da linha y</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="528"/>
        <source>its centre moved by (%1, %2) pixels</source>
        <translation>o seu centro movido de (%1, %2) pixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="529"/>
        <source>mirrored left-right</source>
        <translation>espelhada da esquerda para a direita</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="530"/>
        <source>comparison cancelled</source>
        <translation>comparação cancelada</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="531"/>
        <source>the vertex normals summed over every vertex at the same position instead of by the vertex&apos;s index (a faceted mesh drawn smooth)</source>
        <translation>as normais dos vértices somadas sobre todo vértice na mesma posição em vez de pelo índice do vértice (uma malha facetada desenhada lisa)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="532"/>
        <source>seed 000: a vertex&apos;s normal sums the normals of the triangles that use that vertex, by its index; vertices repeated at one position keep their own</source>
        <translation>semente 000: a normal de um vértice soma as normais dos triângulos que usam aquele vértice, pelo seu índice; vértices repetidos numa posição ficam com a sua</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="533"/>
        <source>our image carried by that map of the screen (each pixel from the nearest of ours) gives their pixels</source>
        <translation>nossa imagem levada por esse mapa da tela (cada pixel do mais próximo dos nossos) dá os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="534"/>
        <source>stretched %1 times across</source>
        <translation>esticada %1 vezes na horizontal</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="535"/>
        <source>stretched %1 times across and %2 times up and down</source>
        <translation>esticada %1 vezes na horizontal e %2 vezes na vertical</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="536"/>
        <source>stretched %1 times up and down</source>
        <translation>esticada %1 vezes na vertical</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="537"/>
        <source>the ratio of the image&apos;s sides (one size used for both axes)</source>
        <translation>a razão entre os lados da imagem (um só tamanho usado para os dois eixos)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="538"/>
        <source>the screen mapped another way: theirs is ours %1 (x&apos; = %2 x + %3 y + %4, y&apos; = %5 x + %6 y + %7)</source>
        <translation>a tela mapeada de outro jeito: a deles é a nossa %1 (x&apos; = %2 x + %3 y + %4, y&apos; = %5 x + %6 y + %7)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="539"/>
        <source>turned %1 degrees clockwise</source>
        <translation>girada %1 graus no sentido horário</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="540"/>
        <source>turned %1 degrees counter-clockwise</source>
        <translation>girada %1 graus no sentido anti-horário</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="541"/>
        <source>turned 90 degrees clockwise</source>
        <translation>girada 90 graus no sentido horário</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="542"/>
        <source>turned 90 degrees counter-clockwise</source>
        <translation>girada 90 graus no sentido anti-horário</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="543"/>
        <source>upside down</source>
        <translation>de cabeça para baixo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="544"/>
        <source>x and y swapped (transposed)</source>
        <translation>com x e y trocados (transposta)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="545"/>
        <source>x and y swapped and both mirrored</source>
        <translation>com x e y trocados e os dois espelhados</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="546"/>
        <source>pixels sampled at their centres (x + 0.5) instead of their corners</source>
        <translation>pixels amostrados nos centros (x + 0.5) em vez dos cantos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="548"/>
        <source>pixels sampled at their corners instead of their centres (x + 0.5)</source>
        <translation>pixels amostrados nos cantos em vez dos centros (x + 0.5)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="550"/>
        <source>vertex positions rounded instead of truncated to whole pixels</source>
        <translation>posições dos vértices arredondadas em vez de truncadas para pixels inteiros</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="551"/>
        <source>vertex positions kept fractional (never made whole) instead of truncated to whole pixels</source>
        <translation>posições dos vértices mantidas fracionárias (nunca tornadas inteiras) em vez de truncadas para pixels inteiros</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="553"/>
        <source>vertex positions truncated instead of rounded to whole pixels</source>
        <translation>posições dos vértices truncadas em vez de arredondadas para pixels inteiros</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="554"/>
        <source>vertex positions rounded instead of truncated to the sub-pixel grid</source>
        <translation>posições dos vértices arredondadas em vez de truncadas para a grade de subpixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="556"/>
        <source>vertex positions truncated instead of rounded to the sub-pixel grid</source>
        <translation>posições dos vértices truncadas em vez de arredondadas para a grade de subpixels</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="558"/>
        <source>vertex positions truncated to the sub-pixel grid instead of kept as computed</source>
        <translation>posições dos vértices truncadas para a grade de subpixels em vez de mantidas como calculadas</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="560"/>
        <source>the top-left fill rule where edges are inclusive</source>
        <translation>a regra de preenchimento top-left onde as arestas são inclusivas</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="561"/>
        <source>inclusive edges where the fill rule is top-left</source>
        <translation>arestas inclusivas onde a regra de preenchimento é top-left</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="562"/>
        <source>colour bytes rounded instead of truncated (off by one)</source>
        <translation>bytes de cor arredondados em vez de truncados (diferença de um)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="563"/>
        <source>colour bytes truncated instead of rounded (off by one)</source>
        <translation>bytes de cor truncados em vez de arredondados (diferença de um)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="564"/>
        <source>colours above 255 wrap around instead of clamping</source>
        <translation>cores acima de 255 dão a volta em vez de serem limitadas a 255</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="565"/>
        <source>the painter&apos;s order (far to near, no depth test) instead of the z-buffer</source>
        <translation>a ordem do pintor (do mais distante ao mais próximo, sem teste de profundidade) em vez do z-buffer</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="567"/>
        <source>z &lt; stored instead of z &lt;= stored in the depth test (ties keep the earlier triangle)</source>
        <translation>z &lt; guardado em vez de z &lt;= guardado no teste de profundidade (empates ficam com o triângulo anterior)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="570"/>
        <source>z &lt;= stored instead of z &lt; stored in the depth test (ties go to the later triangle)</source>
        <translation>z &lt;= guardado em vez de z &lt; guardado no teste de profundidade (empates vão para o triângulo posterior)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="573"/>
        <source>a different background: %1 where the scene&apos;s is %2</source>
        <translation>um fundo diferente: %1 onde o da cena é %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="574"/>
        <source>alpha %1 on covered pixels instead of 255</source>
        <translation>alfa %1 nos pixels cobertos em vez de 255</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="575"/>
        <source>our pixels lit again with that formula (the same triangles, barycentrics, P&apos;, N, lights and material) give theirs</source>
        <translation>nossos pixels iluminados de novo com essa fórmula (os mesmos triângulos, baricêntricas, P&apos;, N, luzes e material) dão os deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="578"/>
        <source>the scene rendered again in that shading model gives their pixels</source>
        <translation>a cena renderizada de novo nesse modelo de sombreamento dá os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="580"/>
        <source>our image moved that way gives their pixels</source>
        <translation>nossa imagem movida assim dá os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="581"/>
        <source>the scene rendered again with that rule gives their pixels</source>
        <translation>a cena renderizada de novo com essa regra dá os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="582"/>
        <source>our float colours made bytes that way give their pixels</source>
        <translation>nossas cores float convertidas em bytes desse jeito dão os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="583"/>
        <source>the scene painted far to near without a depth test gives their pixels</source>
        <translation>a cena pintada do mais distante ao mais próximo, sem teste de profundidade, dá os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="585"/>
        <source>their pixels where no triangle of ours is take that colour</source>
        <translation>os pixels deles onde não há triângulo nosso têm essa cor</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="586"/>
        <source>their pixels where a triangle of ours is take that alpha</source>
        <translation>os pixels deles onde há um triângulo nosso têm esse alfa</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="587"/>
        <source>seed 000&apos;s ambient term is Ia*ka, without the object colour Od</source>
        <translation>o termo ambiente da seed 000 é Ia*ka, sem a cor do objeto Od</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="588"/>
        <source>seed 000: if V.N &lt; 0, N := -N before the lighting</source>
        <translation>seed 000: se V.N &lt; 0, N := -N antes da iluminação</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="589"/>
        <source>seed 000: if R.V &lt; 0, no specular term</source>
        <translation>seed 000: se R.V &lt; 0, sem termo especular</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="590"/>
        <source>seed 000: if N.L &lt; 0, neither diffuse nor specular</source>
        <translation>seed 000: se N.L &lt; 0, nem termo difuso nem especular</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="591"/>
        <source>the interpolated N is shorter than 1: normalise it before N.L and R</source>
        <translation>a N interpolada é mais curta que 1: normalize-a antes de N.L e R</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="593"/>
        <source>check where the lighting is evaluated: per pixel, per vertex or per triangle</source>
        <translation>verifique onde a iluminação é avaliada: por pixel, por vértice ou por triângulo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="596"/>
        <source>check the sign of x in the projection or the screen mapping</source>
        <translation>verifique o sinal de x na projeção ou no mapeamento para a tela</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="597"/>
        <source>screen row 0 is the top: y = (1 - y_ndc) * height / 2</source>
        <translation>a linha 0 da tela é a de cima: y = (1 - y_ndc) * altura / 2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="598"/>
        <source>check the screen mapping&apos;s offsets and the first pixel of each span</source>
        <translation>verifique os deslocamentos do mapeamento para a tela e o primeiro pixel de cada segmento</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="600"/>
        <source>where a pixel is sampled decides which pixels an edge covers (--rules)</source>
        <translation>onde um pixel é amostrado decide quais pixels uma aresta cobre (--rules)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="602"/>
        <source>check how screen coordinates become whole pixels ((int) truncates)</source>
        <translation>verifique como as coordenadas de tela viram pixels inteiros ((int) trunca)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="604"/>
        <source>the pixels exactly on an edge: which triangle (or both) covers them</source>
        <translation>os pixels exatamente sobre uma aresta: qual triângulo (ou ambos) os cobre</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="606"/>
        <source>check how the colour becomes a byte: (int) truncates, + 0.5 rounds</source>
        <translation>verifique como a cor vira um byte: (int) trunca, + 0.5 arredonda</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="608"/>
        <source>clamp each channel to 255 before writing it as a byte</source>
        <translation>limite cada canal a 255 antes de escrevê-lo como byte</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="609"/>
        <source>keep a depth buffer and write a pixel only when the fragment is nearer</source>
        <translation>mantenha um buffer de profundidade e escreva um pixel só quando o fragmento estiver mais perto</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="611"/>
        <source>the comparison of the depth test: &lt; keeps the first of two equal depths</source>
        <translation>a comparação do teste de profundidade: &lt; fica com o primeiro de duas profundidades iguais</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="613"/>
        <source>the colour (and alpha) of the pixels no triangle covers</source>
        <translation>a cor (e o alfa) dos pixels que nenhum triângulo cobre</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="614"/>
        <source>the alpha written with each shaded pixel</source>
        <translation>o alfa escrito com cada pixel sombreado</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="615"/>
        <source>theirs - ours is %1 in %2 of the %3 covered channels that differ</source>
        <translation>deles - nosso é %1 em %2 dos %3 canais cobertos que diferem</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="616"/>
        <source>theirs is within 2 of %1 times ours in %2 of the %3 covered channels that differ</source>
        <translation>o deles está a até 2 de %1 vezes o nosso em %2 dos %3 canais cobertos que diferem</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="618"/>
        <source>the scene rendered again with the fitted lighting gives their pixels</source>
        <translation>a cena renderizada de novo com a iluminação ajustada dá os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="619"/>
        <source>compare the light&apos;s position, the intensities and the coefficients your program uses with the fitted ones</source>
        <translation>compare a posição da luz, as intensidades e os coeficientes que o seu programa usa com os ajustados</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="620"/>
        <source>their lighting, fitted to their colours: %1</source>
        <translation>a iluminação deles, ajustada às cores deles: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="621"/>
        <source>the lighting is fitted for a course camera and one positional light of the course&apos;s model</source>
        <translation>a iluminação é ajustada para uma câmera do curso e uma luz pontual do modelo do curso</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="622"/>
        <source>the lighting is fitted for Phong-shaded draws of one material</source>
        <translation>a iluminação é ajustada para desenhos com sombreamento de Phong de um só material</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="623"/>
        <source>too few unclamped pixels inside triangles to fit the lighting</source>
        <translation>pixels não saturados dentro de triângulos poucos demais para ajustar a iluminação</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="624"/>
        <source>the fitted light is at the light&apos;s world position: it was not taken to view coordinates</source>
        <translation>a luz ajustada está na posição da luz no mundo: ela não foi levada a coordenadas de vista</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="625"/>
        <source>the fitted light is at [I] Pl: C was not subtracted</source>
        <translation>a luz ajustada está em [I] Pl: C não foi subtraído</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="626"/>
        <source>the fitted light is ours with %1 negated</source>
        <translation>a luz ajustada é a nossa com %1 negado</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="627"/>
        <source>the fitted light is ours with %1 and %2 swapped</source>
        <translation>a luz ajustada é a nossa com %1 e %2 trocados</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="628"/>
        <source>the fitted n is half of ours: n halved</source>
        <translation>o n ajustado é metade do nosso: n pela metade</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="629"/>
        <source>the command file read again with that command so gives their pixels</source>
        <translation>o arquivo de comandos lido de novo com esse comando assim dá os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="630"/>
        <source>every &apos;%1&apos; ignored (%2 of them, from line %3): the command never implemented</source>
        <translation>todo &apos;%1&apos; ignorado (%2 deles, a partir da linha %3): o comando nunca foi implementado</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="632"/>
        <source>every &apos;%1&apos; multiplied on the other side (M = A M instead of M A), from line %2</source>
        <translation>todo &apos;%1&apos; multiplicado do outro lado (M = A M em vez de M A), a partir da linha %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="634"/>
        <source>every &apos;%1&apos; read column by column (the matrix transposed), from line %2</source>
        <translation>todo &apos;%1&apos; lido coluna por coluna (a matriz transposta), a partir da linha %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="636"/>
        <source>every &apos;%1&apos; with its angle taken as radians, from line %2</source>
        <translation>todo &apos;%1&apos; com o ângulo tomado em radianos, a partir da linha %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="637"/>
        <source>every &apos;%1&apos; with s = f x up not normalised, from line %2</source>
        <translation>todo &apos;%1&apos; com s = f x up não normalizado, a partir da linha %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="638"/>
        <source>line %1: &apos;%2&apos; ignored</source>
        <translation>linha %1: &apos;%2&apos; ignorado</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="639"/>
        <source>line %1: &apos;%2&apos; multiplied on the other side (M = A M instead of M A)</source>
        <translation>linha %1: &apos;%2&apos; multiplicado do outro lado (M = A M em vez de M A)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="640"/>
        <source>line %1: &apos;%2&apos; read column by column (the matrix transposed)</source>
        <translation>linha %1: &apos;%2&apos; lido coluna por coluna (a matriz transposta)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="641"/>
        <source>line %1: &apos;%2&apos; with its angle taken as radians</source>
        <translation>linha %1: &apos;%2&apos; com o ângulo tomado em radianos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="642"/>
        <source>line %1: &apos;%2&apos; with s = f x up not normalised (the image stretched across)</source>
        <translation>linha %1: &apos;%2&apos; com s = f x up não normalizado (a imagem esticada na horizontal)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="643"/>
        <source>check that your program reads &apos;%1&apos; and applies it</source>
        <translation>verifique se o seu programa lê &apos;%1&apos; e o aplica</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="644"/>
        <source>seed 001: a transform multiplies the model/view on the right, M = M A</source>
        <translation>semente 001: uma transformação multiplica a model/view pela direita, M = M A</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="645"/>
        <source>seed 001 writes a matrix row by row: the first four numbers are its first row</source>
        <translation>a semente 001 escreve uma matriz linha por linha: os quatro primeiros números são a primeira linha</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="646"/>
        <source>seed 001&apos;s angles are in degrees: convert them before sin and cos</source>
        <translation>os ângulos da semente 001 estão em graus: converta-os antes de sin e cos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="647"/>
        <source>lookat: normalise s = f x up before it goes into the matrix</source>
        <translation>lookat: normalize s = f x up antes de pô-lo na matriz</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="648"/>
        <source>the camera&apos;s N not normalised before V - (V.N)N, nor after</source>
        <translation>o N da câmera não normalizado antes de V - (V.N)N, nem depois</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="649"/>
        <source>the camera&apos;s U = V x N instead of N x V (x runs the other way)</source>
        <translation>o U da câmera = V x N em vez de N x V (x corre no outro sentido)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="650"/>
        <source>the scene rendered again in view coordinates made with that basis gives their pixels</source>
        <translation>a cena renderizada de novo em coordenadas de vista feitas com essa base dá os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="651"/>
        <source>seed 000&apos;s Gram-Schmidt: normalise N first, then V - (V.N)N is V&apos;s part across N</source>
        <translation>o Gram-Schmidt da semente 000: normalize N primeiro, então V - (V.N)N é a parte de V transversal a N</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="652"/>
        <source>seed 000: U = N x V, so that U, V, N is right-handed</source>
        <translation>semente 000: U = N x V, para que U, V, N seja uma base dextrógira</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="653"/>
        <source>the vertex normals left at the length of their sums (not normalised)</source>
        <translation>as normais dos vértices deixadas com o comprimento das suas somas (não normalizadas)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="654"/>
        <source>the triangle normals summed at their length (area-weighted) instead of normalised first</source>
        <translation>as normais dos triângulos somadas com o seu comprimento (pesadas pela área) em vez de normalizadas antes</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="655"/>
        <source>seed 000: each vertex normal is the normalised sum of its triangles&apos; normals</source>
        <translation>semente 000: a normal de cada vértice é a soma normalizada das normais dos seus triângulos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="656"/>
        <source>normalise each triangle&apos;s normal before adding it to its vertices</source>
        <translation>normalize a normal de cada triângulo antes de somá-la aos seus vértices</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="657"/>
        <source>the light not taken to view coordinates: its world position used as Pl_view</source>
        <translation>a luz não levada a coordenadas de vista: sua posição no mundo usada como Pl_vista</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="658"/>
        <source>the light taken to view coordinates without subtracting C: [I] Pl instead of [I](Pl - C)</source>
        <translation>a luz levada a coordenadas de vista sem subtrair C: [I] Pl em vez de [I](Pl - C)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="659"/>
        <source>V = P&apos; instead of -P&apos; (L = P&apos; - Pl gives the same image)</source>
        <translation>V = P&apos; em vez de -P&apos; (L = P&apos; - Pl dá a mesma imagem)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="660"/>
        <source>the ambient term Ia instead of Ia*ka</source>
        <translation>o termo ambiente Ia em vez de Ia*ka</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="661"/>
        <source>each Phong term truncated to a whole byte before the sum</source>
        <translation>cada termo de Phong truncado para um byte inteiro antes da soma</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="662"/>
        <source>V.N, N.L and R.V tested against %1 instead of 0</source>
        <translation>V.N, N.L e R.V testados contra %1 em vez de 0</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="663"/>
        <source>the depth test reversed: the farther fragment wins (&gt; against a buffer cleared to -infinity, or to 0)</source>
        <translation>o teste de profundidade invertido: o fragmento mais distante vence (&gt; contra um buffer iniciado com -infinito, ou com 0)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="664"/>
        <source>every covered pixel&apos;s colour off by %1 (a constant offset)</source>
        <translation>a cor de cada pixel coberto deslocada de %1 (um deslocamento constante)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="665"/>
        <source>every colour multiplied by %1 (a constant scale)</source>
        <translation>cada cor multiplicada por %1 (uma escala constante)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="666"/>
        <source>every colour multiplied by 255: a colour scaled by 255 where it was already 0..255</source>
        <translation>cada cor multiplicada por 255: uma cor escalada por 255 onde já era 0..255</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="668"/>
        <source>every colour divided by 255: a colour scaled to 0..1 where the scene&apos;s are 0..255</source>
        <translation>cada cor dividida por 255: uma cor escalada para 0..1 onde as da cena são 0..255</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="670"/>
        <source>the scene rendered again with the light where that transform puts it gives their pixels</source>
        <translation>a cena renderizada de novo com a luz onde essa transformação a coloca dá os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="671"/>
        <source>the scene rendered again with the farther fragment winning gives their pixels</source>
        <translation>a cena renderizada de novo com o fragmento mais distante vencendo dá os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="672"/>
        <source>our bytes moved by that constant give their pixels</source>
        <translation>os nossos bytes deslocados dessa constante dão os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="673"/>
        <source>our colours multiplied by that constant give their pixels</source>
        <translation>as nossas cores multiplicadas por essa constante dão os pixels deles</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="674"/>
        <source>seed 000: the light goes to view coordinates as the vertices do, Pl_view = [I](Pl - C)</source>
        <translation>semente 000: a luz vai para coordenadas de vista como os vértices, Pl_vista = [I](Pl - C)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="675"/>
        <source>seed 000: Pl_view = [I](Pl - C): subtract C before the change of basis</source>
        <translation>semente 000: Pl_vista = [I](Pl - C): subtraia C antes da mudança de base</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="676"/>
        <source>V points from the surface to the camera: V = -P&apos; in view coordinates, and L = Pl - P&apos;</source>
        <translation>V aponta da superfície para a câmera: V = -P&apos; em coordenadas de vista, e L = Pl - P&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="677"/>
        <source>seed 000&apos;s ambient term is Ia*ka</source>
        <translation>o termo ambiente da semente 000 é Ia*ka</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="678"/>
        <source>add the terms as real numbers and make a byte once, at the end</source>
        <translation>some os termos como números reais e faça um byte uma vez, no fim</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="679"/>
        <source>seed 000&apos;s special cases test against 0: V.N &lt; 0, N.L &lt; 0, R.V &lt; 0</source>
        <translation>os casos especiais da semente 000 testam contra 0: V.N &lt; 0, N.L &lt; 0, R.V &lt; 0</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="680"/>
        <source>the z-buffer starts at +infinity and a fragment is written when its z is smaller</source>
        <translation>o z-buffer começa em +infinito e um fragmento é escrito quando seu z é menor</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="681"/>
        <source>look for a constant added to every colour, or bytes made with an offset</source>
        <translation>procure uma constante somada a cada cor, ou bytes feitos com um deslocamento</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="682"/>
        <source>look for a factor on every colour: an intensity scaled, or another colour scale</source>
        <translation>procure um fator em cada cor: uma intensidade escalada, ou outra escala de cor</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="683"/>
        <source>%1; no pixel that matches now would change</source>
        <translation>%1; nenhum pixel que coincide agora mudaria</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="684"/>
        <source>%2; %1 pixel that matches now would differ</source>
        <translation>%2; %1 pixel que coincide agora passaria a diferir</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="685"/>
        <source>%2; %1 pixels that match now would differ</source>
        <translation>%2; %1 pixels que coincidem agora passariam a diferir</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="687"/>
        <source>cannot read the texture %1: %2</source>
        <translation>não é possível ler a textura %1: %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="689"/>
        <source>V is %1 degrees from the line of N: Gram-Schmidt keeps only that much of V, and the basis is orthonormal only to %2, less than a float&apos;s precision; choose a V farther from N</source>
        <translation>V está a %1 graus da reta de N: Gram-Schmidt guarda só isso de V, e a base é ortonormal só até %2, menos que a precisão de um float; escolha um V mais longe de N</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="694"/>
        <source>cannot open: %1</source>
        <translation>não é possível abrir: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="695"/>
        <source>the file has %1 MiB, more than the %2 MiB an input file may have</source>
        <translation>o arquivo tem %1 MiB, mais que os %2 MiB que um arquivo de entrada pode ter</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="697"/>
        <source>the file has more than the %1 MiB an input file may have</source>
        <translation>o arquivo tem mais que os %1 MiB que um arquivo de entrada pode ter</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="699"/>
        <source>not enough memory to read this file</source>
        <translation>não há memória suficiente para ler este arquivo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="700"/>
        <source>the built-in scene&apos;s files cannot be written: save it to a file of your own (Save As)</source>
        <translation>os arquivos da cena embutida não podem ser gravados: salve-a num arquivo seu (Salvar como)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="703"/>
        <source>the object is not edited, so not saved</source>
        <translation>o objeto não é editado, então não é salvo</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="704"/>
        <source>cannot write into the built-in resources</source>
        <translation>não é possível gravar nos recursos embutidos</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="705"/>
        <source>the camera was not saved, as it would not load again: %1</source>
        <translation>a câmera não foi salva, pois não carregaria de novo: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="706"/>
        <source>not saved: the text written does not read back as the same values</source>
        <translation>não salvo: o texto gravado não é lido de volta com os mesmos valores</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="708"/>
        <source>cannot write the file: %1</source>
        <translation>não é possível gravar o arquivo: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="709"/>
        <source>only %1 of %2 bytes could be written (is the disk full?)</source>
        <translation>só %1 de %2 bytes puderam ser gravados (o disco está cheio?)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="710"/>
        <source>cannot write the file (it is left as it was): %1</source>
        <translation>não é possível gravar o arquivo (ele fica como estava): %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="712"/>
        <source>[rows, fragments], two whole numbers</source>
        <translation>[linhas, fragmentos], dois números inteiros</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="713"/>
        <source>[width, height], whole numbers from %1 to %2</source>
        <translation>[largura, altura], números inteiros de %1 a %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="714"/>
        <source>a list</source>
        <translation>uma lista</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="715"/>
        <source>a list of %1 numbers</source>
        <translation>uma lista de %1 números</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="716"/>
        <source>a list of 1 to 8 lights</source>
        <translation>uma lista de 1 a 8 luzes</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="717"/>
        <source>a list of dock names</source>
        <translation>uma lista de nomes de painéis</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="718"/>
        <source>a number</source>
        <translation>um número</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="719"/>
        <source>a positive number or &quot;auto&quot;</source>
        <translation>um número positivo ou &quot;auto&quot;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="720"/>
        <source>a positive number or &quot;fit&quot;</source>
        <translation>um número positivo ou &quot;fit&quot;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="721"/>
        <source>a whole number from %1</source>
        <translation>um número inteiro a partir de %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="722"/>
        <source>an object</source>
        <translation>um objeto</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="723"/>
        <source>expected %1 for &quot;%2&quot;, found %3</source>
        <translation>esperava %1 para &quot;%2&quot;, encontrou %3</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="724"/>
        <source>expected a lesson file: a JSON object with &quot;rasterlab_lesson&quot;: %1</source>
        <translation>esperava um arquivo de aula: um objeto JSON com &quot;rasterlab_lesson&quot;: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="726"/>
        <source>not a lesson file: %1</source>
        <translation>não é um arquivo de aula: %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="727"/>
        <source>nothing</source>
        <translation>nada</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="728"/>
        <source>null</source>
        <translation>null</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="729"/>
        <source>one of %1</source>
        <translation>um de %1</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="730"/>
        <source>text in quotes</source>
        <translation>um texto entre aspas</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="731"/>
        <source>the text &apos;%1&apos;</source>
        <translation>o texto &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="732"/>
        <source>true or false</source>
        <translation>true ou false</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="733"/>
        <source>unknown key &quot;%1&quot; ignored (known here: %2)</source>
        <translation>ignorou a chave desconhecida &quot;%1&quot; (as conhecidas aqui: %2)</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="768"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="774"/>
        <source>%1: warning: %2</source>
        <translation>%1: aviso: %2</translation>
    </message>
    <message>
        <location filename="../views/messages/pipeline_messages.cpp" line="775"/>
        <source>%1: note: %2</source>
        <translation>%1: nota: %2</translation>
    </message>
</context>
<context>
    <name>StabilityPlot</name>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="156"/>
        <source>every point: error against time</source>
        <translation>todos os pontos: erro contra tempo</translation>
    </message>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="157"/>
        <source>time per frame (ms, log scale)</source>
        <translation>tempo por quadro (ms, escala log)</translation>
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
        <translation>float contra double, maior diferença</translation>
    </message>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="194"/>
        <source>y: colour error in byte steps (log; RMSE against the exact reference, or the largest float-double difference); x: stiffer to the right; a cross: the scene could not be rendered</source>
        <translation>y: erro de cor em passos de byte (log; RMSE contra a referência exata, ou a maior diferença float-double); x: mais rígido à direita; um x: a cena não pôde ser renderizada</translation>
    </message>
    <message>
        <location filename="../app/plots/stability_plot.cpp" line="268"/>
        <source>%1 (%2, log scale)</source>
        <translation>%1 (%2, escala log)</translation>
    </message>
</context>
<context>
    <name>rasterlab::AccuracyPanel</name>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="85"/>
        <source>The scene, camera and lights moved %1 to %2 units from the origin</source>
        <translation>A cena, a câmera e as luzes deslocadas de %1 a %2 unidades da origem</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="90"/>
        <source>Everything scaled by %1 to %2 about the origin</source>
        <translation>Tudo escalado por %1 a %2 em torno da origem</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="94"/>
        <source>Everything scaled by %1 to %2 about the eye: the object nearer</source>
        <translation>Tudo escalado por %1 a %2 em torno do olho: o objeto mais perto</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="97"/>
        <source>Each triangle cut around a sliver of %1 to %2 degrees</source>
        <translation>Cada triângulo cortado em torno de uma lasca de %1 a %2 graus</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="100"/>
        <source>Every material&apos;s shininess n set to %1 to %2</source>
        <translation>O brilho n de cada material posto de %1 a %2</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="103"/>
        <source>The camera&apos;s V %1 to %2 degrees from N</source>
        <translation>O V da câmera a %1 até %2 graus de N</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="106"/>
        <source>The first light %1 to %2 times the scene&apos;s size above its surface</source>
        <translation>A primeira luz a %1 até %2 vezes o tamanho da cena acima da sua superfície</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="152"/>
        <source>float and double differ by up to %1 byte steps (at %2); largest RMSE, float / double: %3.</source>
        <translation>float e double diferem em até %1 passos de byte (em %2); maior RMSE, float / double: %3.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="159"/>
        <source>%1 of %2 points not rendered (the first at %3): %4</source>
        <translation>%1 de %2 pontos não renderizados (o primeiro em %3): %4</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="177"/>
        <source>&amp;Measure</source>
        <translation>&amp;Medir</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="180"/>
        <source>Render the scene in every mode and compare each with an exact ray-cast reference</source>
        <translation>Renderiza a cena em cada modo e compara cada um com uma referência exata por lançamento de raios</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="182"/>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="187"/>
        <source>1 sample a pixel</source>
        <translation>1 amostra por pixel</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="188"/>
        <source>also 2x2 samples</source>
        <translation>também 2x2 amostras</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="189"/>
        <source>also 4x4 samples</source>
        <translation>também 4x4 amostras</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="196"/>
        <source>&amp;Stability sweep</source>
        <translation>&amp;Varredura de estabilidade</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="199"/>
        <source>Make the scene stiffer step by step and measure float and double under the course and gpu rules against the exact reference at each step</source>
        <translation>Torna a cena mais rígida passo a passo e mede float e double sob as regras course e gpu contra a referência exata a cada passo</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="203"/>
        <source>every axis</source>
        <translation>todos os eixos</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="208"/>
        <source>The axes of stiffness to sweep</source>
        <translation>Os eixos de rigidez a varrer</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="214"/>
        <source>%v of %m points</source>
        <translation>%v de %m pontos</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="218"/>
        <source>Measures the error of each mode against an exact reference.</source>
        <translation>Mede o erro de cada modo contra uma referência exata.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="225"/>
        <source>Modes</source>
        <translation>Modos</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="226"/>
        <source>Stability</source>
        <translation>Estabilidade</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="245"/>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="245"/>
        <source>Rules</source>
        <translation>Regras</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="245"/>
        <source>Precision</source>
        <translation>Precisão</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="245"/>
        <source>Samples</source>
        <translation>Amostras</translation>
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
        <translation>Erro máximo</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="246"/>
        <source>Within 1/255</source>
        <translation>Dentro de 1/255</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="247"/>
        <source>Errors in byte steps (1/255) over the pixels both images cover</source>
        <translation>Erros em passos de byte (1/255) nos pixels que as duas imagens cobrem</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="271"/>
        <source>Click a pixel to compare the mode with the reference there</source>
        <translation>Clique num pixel para comparar ali o modo com a referência</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="300"/>
        <source>The sweep makes the scene stiffer along each axis: where a curve leaves the floor, the arithmetic loses accuracy.</source>
        <translation>A varredura torna a cena mais rígida ao longo de cada eixo: onde uma curva sai do piso, a aritmética perde exatidão.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="334"/>
        <source>The scene changed: measure again.</source>
        <translation>A cena mudou: meça de novo.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/window/accuracy_panel.cpp" line="356"/>
        <source>Measuring %n mode(s) against the exact reference...</source>
        <translation>
            <numerusform>Medindo %n modo contra a referência exata...</numerusform>
            <numerusform>Medindo %n modos contra a referência exata...</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="379"/>
        <source>Cancelled.</source>
        <translation>Cancelado.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="380"/>
        <source>The measurement failed: %1</source>
        <translation>A medição falhou: %1</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="386"/>
        <source>%1 at %2x%3: %4 modes; the exact reference cast %5 rays in %6 ms.</source>
        <translation>%1 em %2x%3: %4 modos; a referência exata lançou %5 raios em %6 ms.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="413"/>
        <source>Error against run time: %1, %2x%3</source>
        <translation>Erro contra tempo de execução: %1, %2x%3</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="457"/>
        <source>Sweeping %1 along %2...</source>
        <translation>Varrendo %1 ao longo de %2...</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="482"/>
        <source>Sweep cancelled.</source>
        <translation>Varredura cancelada.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="483"/>
        <source>The sweep failed: %1</source>
        <translation>A varredura falhou: %1</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="490"/>
        <source>Error against stiffness: %1, %2x%3, %4 triangles</source>
        <translation>Erro contra rigidez: %1, %2x%3, %4 triângulos</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="496"/>
        <source>%1 at %2x%3: %4 points in %5 s.</source>
        <translation>%1 em %2x%3: %4 pontos em %5 s.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="552"/>
        <source>%1 (%2): coverage differs on %3 pixels (%4); the largest error, %5 byte steps, is at (%6, %7). Click the map to compare a pixel.</source>
        <translation>%1 (%2): a cobertura difere em %3 pixels (%4); o maior erro, %5 passos de byte, está em (%6, %7). Clique no mapa para comparar um pixel.</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="571"/>
        <source>Pixel (%1, %2), %3: mode %4, reference %5, difference %6 (byte steps).</source>
        <translation>Pixel (%1, %2), %3: modo %4, referência %5, diferença %6 (passos de byte).</translation>
    </message>
    <message>
        <location filename="../app/window/accuracy_panel.cpp" line="577"/>
        <source>Coverage differs: %1 of %2 samples covered by the mode, %3 by the reference.</source>
        <translation>A cobertura difere: %1 de %2 amostras cobertas pelo modo, %3 pela referência.</translation>
    </message>
</context>
<context>
    <name>rasterlab::AnimationPanel</name>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="30"/>
        <source>Animate: each draw moved by M(t)</source>
        <translation>Animar: cada desenho movido por M(t)</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="35"/>
        <location filename="../app/window/animation_panel.cpp" line="210"/>
        <source>Play</source>
        <translation>Reproduzir</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="40"/>
        <source>Play or pause the animation; paused, every stage view inspects the frame shown</source>
        <translation>Reproduz ou pausa a animação; pausada, o painel de cada etapa inspeciona o quadro exibido</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="61"/>
        <source>Frames:</source>
        <translation>Quadros:</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="64"/>
        <source>Frames a second:</source>
        <translation>Quadros por segundo:</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="67"/>
        <source> °/s</source>
        <translation> °/s</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="68"/>
        <source>Turn:</source>
        <translation>Rotação:</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="69"/>
        <source>Turn about the camera&apos;s up (a turntable)</source>
        <translation>Girar em torno do vetor para cima da câmera (uma mesa giratória)</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="97"/>
        <source>Axis:</source>
        <translation>Eixo:</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="99"/>
        <source>Moves (units/s):</source>
        <translation>Translação (unidades/s):</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="100"/>
        <source>Scale:</source>
        <translation>Escala:</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="111"/>
        <source>&lt;i&gt;The animation belongs to this session: course files have no such field, and saving the camera or lighting does not write it.&lt;/i&gt;</source>
        <translation>&lt;i&gt;A animação pertence a esta sessão: os arquivos do curso não têm esse campo, e salvar a câmera ou a iluminação não a grava.&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="210"/>
        <source>Pause</source>
        <translation>Pausar</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="222"/>
        <source>Frame %1 of %2, t = %3 / %4 = %5 s</source>
        <translation>Quadro %1 de %2, t = %3 / %4 = %5 s</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="241"/>
        <source>&lt;p&gt;M(t) = T(v t) · T(c) · R(axis, ω t) · S · T(−c): not applied (the animation is off, so M is the identity).&lt;/p&gt;</source>
        <translation>&lt;p&gt;M(t) = T(v t) · T(c) · R(eixo, ω t) · S · T(−c): não aplicada (a animação está desligada, então M é a identidade).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="257"/>
        <source>&lt;p&gt;M(t) = T(v t) · T(c) · R(axis, ω t) · S · T(−c), at t = %1 s:&lt;br&gt;c = %2 (the centre of the bounding box), axis = %3,&lt;br&gt;ω t = %4 °/s · %1 s = %5°, v t = %6, S = diag%7&lt;/p&gt;</source>
        <translation>&lt;p&gt;M(t) = T(v t) · T(c) · R(eixo, ω t) · S · T(−c), em t = %1 s:&lt;br&gt;c = %2 (o centro da caixa envolvente), eixo = %3,&lt;br&gt;ω t = %4 °/s · %1 s = %5°, v t = %6, S = diag%7&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/animation_panel.cpp" line="265"/>
        <source>&lt;p&gt;Normals are moved by the inverse transpose of M (stage 3).&lt;/p&gt;</source>
        <translation>&lt;p&gt;As normais são levadas pela inversa transposta de M (etapa 3).&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>rasterlab::BreakpointsView</name>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="37"/>
        <source>triangle %1 starts</source>
        <translation>o triângulo %1 começa</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="39"/>
        <source>a triangle reaches scanline %1</source>
        <translation>um triângulo chega à linha de varredura %1</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="41"/>
        <source>first depth rejection at (%1, %2)</source>
        <translation>1ª rejeição de profundidade em (%1, %2)</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="43"/>
        <source>N.L &lt; 0 at (%1, %2)</source>
        <translation>N.L &lt; 0 em (%1, %2)</translation>
    </message>
    <message numerus="yes">
        <location filename="../views/breakpoints_view.cpp" line="45"/>
        <source>any pixel written %n time(s)</source>
        <translation>
            <numerusform>qualquer pixel escrito %n vez</numerusform>
            <numerusform>qualquer pixel escrito %n vezes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../views/breakpoints_view.cpp" line="46"/>
        <source>(%1, %2) written %n time(s)</source>
        <translation>
            <numerusform>(%1, %2) escrito %n vez</numerusform>
            <numerusform>(%1, %2) escrito %n vezes</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="60"/>
        <source>At triangle</source>
        <translation>No triângulo</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="61"/>
        <source>At scanline</source>
        <translation>Na linha de varredura</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="62"/>
        <source>First depth rejection at the picked pixel</source>
        <translation>1ª rejeição no pixel escolhido</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="64"/>
        <source>N.L &lt; 0 at the picked pixel</source>
        <translation>N.L &lt; 0 no pixel escolhido</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="65"/>
        <source>A pixel written n times</source>
        <translation>Um pixel escrito n vezes</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="66"/>
        <source>Stop when</source>
        <translation>Parar quando</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="70"/>
        <source>Number</source>
        <translation>Número</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="72"/>
        <source>the picked pixel</source>
        <translation>o pixel escolhido</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="73"/>
        <source>any pixel</source>
        <translation>qualquer pixel</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="74"/>
        <source>Pixel</source>
        <translation>Pixel</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="77"/>
        <source>&amp;Add</source>
        <translation>A&amp;dicionar</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="79"/>
        <source>&amp;Remove</source>
        <translation>&amp;Remover</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="80"/>
        <source>Remove A&amp;ll</source>
        <translation>Remover &amp;todos</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="90"/>
        <source>Breakpoint</source>
        <translation>Ponto de parada</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="98"/>
        <source>Pick a pixel in the image first.</source>
        <translation>Escolha antes um pixel na imagem.</translation>
    </message>
    <message>
        <location filename="../views/breakpoints_view.cpp" line="115"/>
        <source>Stopped: %1</source>
        <translation>Parado: %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::CameraBasisCanvas</name>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="155"/>
        <source>Drag to turn the scene, wheel to zoom, double-click to reset.</source>
        <translation>Arraste para girar a cena, use a roda para o zoom, clique duas vezes para restaurar.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="158"/>
        <source>Reset view</source>
        <translation>Restaurar vista</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="159"/>
        <source>Turn the 3D drawing back to where it started</source>
        <translation>Volta o desenho 3D à posição inicial</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="422"/>
        <source>window (d = %1)</source>
        <translation>janela (d = %1)</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="426"/>
        <source>frustum</source>
        <translation>volume de visão</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="441"/>
        <source>N given, |N| = %1</source>
        <translation>N dado, |N| = %1</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="444"/>
        <source>V given, |V| = %1</source>
        <translation>V dado, |V| = %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::CameraBasisView</name>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="512"/>
        <source>Previous step</source>
        <translation>Passo anterior</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="516"/>
        <source>Next step</source>
        <translation>Próximo passo</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="634"/>
        <source>The camera was rejected: %1</source>
        <translation>A câmera foi rejeitada: %1</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="637"/>
        <source>No frame yet.</source>
        <translation>Nenhum quadro ainda.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="639"/>
        <source>This stage is skipped: %1.</source>
        <translation>Esta etapa é omitida: %1.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="641"/>
        <source>the frame has no camera basis</source>
        <translation>o quadro não tem base da câmera</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="648"/>
        <source>&lt;p&gt;&lt;b&gt;Camera basis.&lt;/b&gt; From the course camera (C, N, V) Gram-Schmidt makes the orthonormal basis U, V, N of view space. A scene whose draws carry their own model/view matrices (HW2 command files) has no course camera: this stage does nothing for it.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Base da câmera.&lt;/b&gt; A partir da câmera do curso (C, N, V), Gram-Schmidt constrói a base ortonormal U, V, N do espaço de vista. Uma cena cujos desenhos trazem suas próprias matrizes de modelo/vista (arquivos de comandos HW2) não tem câmera do curso: esta etapa não faz nada para ela.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="661"/>
        <source>N and V are nearly parallel: |V − (V·N) N| / |V| = %1, below %2. The basis is ill-conditioned: a tiny change of N or V turns U and V a lot. Choose a V further from N.</source>
        <translation>N e V são quase paralelos: |V − (V·N) N| / |V| = %1, abaixo de %2. A base é mal condicionada: uma mudança mínima de N ou V gira muito U e V. Escolha um V mais afastado de N.</translation>
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
        <translation>U·V = %1, U·N = %2, V·N = %3, |U| − 1 = %4, |V| − 1 = %5, |N| − 1 = %6; maior %7</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="691"/>
        <source>N and V %1 degrees apart (under %2 degrees from the line of N, the residuals pass a float&apos;s precision)</source>
        <translation>N e V a %1 graus um do outro (a menos de %2 graus da reta de N, os resíduos passam a precisão de um float)</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="713"/>
        <source>&lt;b&gt;viewFromWorld&lt;/b&gt; = [U; V; N] · translate(−C): rows U, V, N, then (0 0 0 1); the last column is −U·C, −V·C, −N·C.</source>
        <translation>&lt;b&gt;viewFromWorld&lt;/b&gt; = [U; V; N] · translate(−C): linhas U, V, N e depois (0 0 0 1); a última coluna é −U·C, −V·C, −N·C.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="725"/>
        <source>&lt;p&gt;Vertex 1: P = %1, P − C = %2, pView = (U·(P − C), V·(P − C), N·(P − C)) = %3%4.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Vértice 1: P = %1, P − C = %2, pView = (U·(P − C), V·(P − C), N·(P − C)) = %3%4.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="728"/>
        <source>, in front of the camera (z &gt; 0)</source>
        <translation>, à frente da câmera (z &gt; 0)</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="729"/>
        <source>, behind the camera (z ≤ 0)</source>
        <translation>, atrás da câmera (z ≤ 0)</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="732"/>
        <source>&lt;p&gt;&lt;b&gt;Camera basis.&lt;/b&gt; Gram-Schmidt keeps the direction of N (where the camera looks), removes from V its part along N so that up is perpendicular to the view direction, and completes the frame with U = N × V, the image&apos;s right. viewFromWorld = [U; V; N] (P − C) puts the camera at the origin looking along +z.&lt;/p&gt;&lt;p&gt;C = %1, N = %2, V = %3, d = %4, hx = %5, hy = %6.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Base da câmera.&lt;/b&gt; Gram-Schmidt mantém a direção de N (para onde a câmera olha), remove de V sua componente ao longo de N para que o &quot;para cima&quot; fique perpendicular à direção de visão, e completa o referencial com U = N × V, a direita da imagem. viewFromWorld = [U; V; N] (P − C) põe a câmera na origem olhando ao longo de +z.&lt;/p&gt;&lt;p&gt;C = %1, N = %2, V = %3, d = %4, hx = %5, hy = %6.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="764"/>
        <source>Step %1 of 4</source>
        <translation>Passo %1 de 4</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="779"/>
        <source>Step forward to normalise N.</source>
        <translation>Avance um passo para normalizar N.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="780"/>
        <source>Step forward to remove from V its part along N.</source>
        <translation>Avance um passo para remover de V sua componente ao longo de N.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="781"/>
        <source>Step forward to normalise V.</source>
        <translation>Avance um passo para normalizar V.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="782"/>
        <source>Step forward to make U = N × V.</source>
        <translation>Avance um passo para obter U = N × V.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="783"/>
        <source>The basis is complete; the frustum is drawn with it.</source>
        <translation>A base está completa; o volume de visão (o frustum, tronco de pirâmide que a câmera vê) é desenhado com ela.</translation>
    </message>
    <message>
        <location filename="../views/camera_basis_view.cpp" line="796"/>
        <source>&lt;b&gt;Orthonormality residuals&lt;/b&gt; (0 up to rounding): %1</source>
        <translation>&lt;b&gt;Resíduos de ortonormalidade&lt;/b&gt; (0 a menos de arredondamento): %1</translation>
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
        <translation>O comando que inicia o seu programa, executado pelo /bin/sh na pasta abaixo; ele responde ao protocolo de etapas na sua entrada e saída padrão (docs/stage-protocol.md).</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="58"/>
        <source>Command:</source>
        <translation>Comando:</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="62"/>
        <source>Browse...</source>
        <translation>Procurar...</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="65"/>
        <source>Folder:</source>
        <translation>Pasta:</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="69"/>
        <source>Check</source>
        <translation>Verificar</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="71"/>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="73"/>
        <source>Stop at the First Departure</source>
        <translation>Parar no Primeiro Desvio</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="75"/>
        <source>Step the frame to where the selected stage first departs from the lecture&apos;s</source>
        <translation>Avança o quadro até onde a etapa selecionada se desvia pela primeira vez da etapa da aula</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="81"/>
        <source>Chained</source>
        <translation>Encadeada</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="83"/>
        <source>Give each stage your program&apos;s own earlier answers as its input, to see how errors add up (unticked, each stage gets RasterLab&apos;s, so no mistake hides another)</source>
        <translation>Dá a cada etapa as respostas anteriores do seu próprio programa como entrada, para ver como os erros se somam (desmarcada, cada etapa recebe as do RasterLab, e nenhum erro esconde outro)</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="95"/>
        <source>Compare Their Frame</source>
        <translation>Comparar o Quadro Deles</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="97"/>
        <source>Their whole frame in the Compare dock: each pixel&apos;s colour beside ours, and the Phong term that would have to change</source>
        <translation>O quadro inteiro deles no painel Comparar: a cor de cada pixel ao lado da nossa, e o termo de Phong que teria de mudar</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="114"/>
        <source>Stage</source>
        <translation>Etapa</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="114"/>
        <source>Verdict</source>
        <translation>Veredito</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="114"/>
        <source>Elements</source>
        <translation>Elementos</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="114"/>
        <source>Likely cause</source>
        <translation>Causa provável</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="151"/>
        <source>Your Program&apos;s Folder</source>
        <translation>A Pasta do Seu Programa</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="194"/>
        <source>A check is running.</source>
        <translation>Uma verificação está em andamento.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="196"/>
        <source>Give the command that starts your program.</source>
        <translation>Informe o comando que inicia o seu programa.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="199"/>
        <source>The folder %1 does not exist.</source>
        <translation>A pasta %1 não existe.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="201"/>
        <source>There is no frame to check against.</source>
        <translation>Não há quadro com que comparar.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="225"/>
        <source>Checking %1...</source>
        <translation>Verificando %1...</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="243"/>
        <source>cancelled</source>
        <translation>cancelada</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="243"/>
        <source>done</source>
        <translation>concluída</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="253"/>
        <source>Over our image: each vertex that departs, ours a green dot, theirs a red cross, joined by a line.</source>
        <translation>Sobre a nossa imagem: cada vértice que se desvia, o nosso um ponto verde, o deles uma cruz vermelha, unidos por uma linha.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="257"/>
        <source>Over our image: magenta, pixels only we cover; cyan, pixels only they cover.</source>
        <translation>Sobre a nossa imagem: magenta, pixels que só nós cobrimos; ciano, pixels que só eles cobrem.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="261"/>
        <source>Over our image: red, pixels another triangle wins (or at another depth); magenta, only ours keeps one; cyan, only theirs.</source>
        <translation>Sobre a nossa imagem: vermelho, pixels que outro triângulo ganha (ou com outra profundidade); magenta, só o nosso guarda um; ciano, só o deles.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="265"/>
        <source>Over our image: red, pixels whose colour differs by more than 1.</source>
        <translation>Sobre a nossa imagem: vermelho, pixels cuja cor difere em mais de 1.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="274"/>
        <source>passed</source>
        <translation>passou</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="276"/>
        <source>failed</source>
        <translation>falhou</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="278"/>
        <source>unsupported</source>
        <translation>não suportada</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="280"/>
        <source>broken</source>
        <translation>quebrou</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="323"/>
        <source>not applied: %1</source>
        <translation>não aplicado: %1</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="332"/>
        <source>Protected by: %1.</source>
        <translation>Protegido por: %1.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="333"/>
        <source>Protected by: %1. Not applied: %2.</source>
        <translation>Protegido por: %1. Não aplicado: %2.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="337"/>
        <source>Not checked: %1</source>
        <translation>Não verificada: %1</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="343"/>
        <source>%1 of %2 differ</source>
        <translation>%1 de %2 diferem</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="361"/>
        <source>Every stage passed (%1 s).</source>
        <translation>Todas as etapas passaram (%1 s).</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="410"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="414"/>
        <source>First departure: %1: theirs %2, ours %3</source>
        <translation>Primeiro desvio: %1: o deles %2, o nosso %3</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="419"/>
        <source>Likely cause: %1 (explains %2 of %3, %4% of the difference)</source>
        <translation>Causa provável: %1 (explica %2 de %3, %4% da diferença)</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="425"/>
        <source>No known mistake of this stage gives their answer.</source>
        <translation>Nenhum erro conhecido desta etapa dá a resposta deles.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="427"/>
        <source>Unexplained: %1 of %2.</source>
        <translation>Sem explicação: %1 de %2.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="428"/>
        <source>In numbers: %1</source>
        <translation>Em números: %1</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="430"/>
        <source>Carried from the earlier stages: %1 elements of the lecture&apos;s answer change with what was sent.</source>
        <translation>Trazido das etapas anteriores: %1 elementos da resposta da aula mudam com o que foi enviado.</translation>
    </message>
    <message>
        <location filename="../app/window/check_panel.cpp" line="435"/>
        <source>Tolerance: %1</source>
        <translation>Tolerância: %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::CompareImage</name>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="102"/>
        <source>no such file</source>
        <translation>o arquivo não existe</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="106"/>
        <source>the file is empty</source>
        <translation>o arquivo está vazio</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="130"/>
        <source>the PNG is cut short (it does not end with its IEND chunk)</source>
        <translation>o PNG está cortado (não termina com o seu bloco IEND)</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="104"/>
        <source>a folder, not an image</source>
        <translation>uma pasta, não uma imagem</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="29"/>
        <source>the TGA header is cut short</source>
        <translation>o cabeçalho do TGA está cortado</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="37"/>
        <source>a TGA image of a kind RasterLab does not read (only 8-bit grey and 24- or 32-bit colour, plain or run-length encoded)</source>
        <translation>uma imagem TGA de um tipo que o RasterLab não lê (só cinza de 8 bits e cor de 24 ou 32 bits, simples ou com codificação por carreiras)</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="49"/>
        <location filename="../app/compare/compare_image.cpp" line="75"/>
        <source>the TGA image is cut short</source>
        <translation>a imagem TGA está cortada</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="53"/>
        <source>the TGA image is %1x%2, larger than RasterLab reads</source>
        <translation>a imagem TGA tem %1x%2, maior do que o RasterLab lê</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="125"/>
        <source>not an image RasterLab reads (PNG, PPM, BMP, TGA or JPEG)</source>
        <translation>não é uma imagem que o RasterLab lê (PNG, PPM, BMP, TGA ou JPEG)</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="126"/>
        <source>not an image RasterLab reads (PNG, PPM, BMP, TGA or JPEG): a %1 image</source>
        <translation>não é uma imagem que o RasterLab lê (PNG, PPM, BMP, TGA ou JPEG): é uma imagem %1</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="144"/>
        <source>cannot read the %1 image: %2</source>
        <translation>não é possível ler a imagem %1: %2</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="172"/>
        <source>a %1 image</source>
        <translation>uma imagem %1</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="174"/>
        <source>, lossy: compared with a tolerance of %1 per channel</source>
        <translation>, com perdas: comparada com uma tolerância de %1 por canal</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="175"/>
        <source>, without alpha: colours compared, alpha taken as ours</source>
        <translation>, sem alfa: cores comparadas, alfa tomado como o nosso</translation>
    </message>
    <message>
        <location filename="../app/compare/compare_image.cpp" line="205"/>
        <source>the image is %1, ours is %2</source>
        <translation>a imagem tem %1, a nossa tem %2</translation>
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
        <translation>vermelho</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="27"/>
        <source>green</source>
        <translation>verde</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="29"/>
        <source>blue</source>
        <translation>azul</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="31"/>
        <source>alpha</source>
        <translation>alfa</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="38"/>
        <source>%1 and %2</source>
        <translation>%1 e %2</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="163"/>
        <source>Side by side</source>
        <translation>Lado a lado</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="164"/>
        <source>Flicker</source>
        <translation>Alternar</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="165"/>
        <source>Difference</source>
        <translation>Diferença</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="167"/>
        <source>Theirs beside ours, one after the other twice a second, or the pixels that differ</source>
        <translation>A deles ao lado da nossa, uma depois da outra duas vezes por segundo, ou os pixels que diferem</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="170"/>
        <source>Differ by more than</source>
        <translation>Diferem em mais de</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="176"/>
        <source>The difference view shows the pixels where some channel differs by more than this (0: every difference)</source>
        <translation>A vista da diferença mostra os pixels em que algum canal difere em mais do que isto (0: toda diferença)</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="181"/>
        <source>Compare Again</source>
        <translation>Comparar de novo</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="184"/>
        <source>The scene changed since the comparison: compare their image with the scene shown now</source>
        <translation>A cena mudou desde a comparação: comparar a imagem deles com a cena mostrada agora</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="219"/>
        <source>File &gt; Compare with Image... compares a PNG of your own renderer with this scene&apos;s render.</source>
        <translation>Arquivo &gt; Comparar com imagem... compara um PNG do seu próprio renderizador com a renderização desta cena.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="308"/>
        <source>There is no render to compare with yet.</source>
        <translation>Ainda não há renderização com que comparar.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="271"/>
        <source>Their image: %1.</source>
        <translation>A imagem deles: %1.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="282"/>
        <source>Cropped to %1x%2 at (%3, %4) from %5x%6: the frame found inside it.</source>
        <translation>Recortada para %1x%2 em (%3, %4) a partir de %5x%6: o quadro encontrado dentro dela.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="435"/>
        <location filename="../app/window/compare_panel.cpp" line="438"/>
        <source>Theirs</source>
        <translation>Deles</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="435"/>
        <location filename="../app/window/compare_panel.cpp" line="438"/>
        <source>Ours</source>
        <translation>Nossa</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/window/compare_panel.cpp" line="443"/>
        <source>%n pixel(s) differ by more than %1</source>
        <translation>
            <numerusform>%n pixel difere em mais de %1</numerusform>
            <numerusform>%n pixels diferem em mais de %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="521"/>
        <source>%1 against our render (%2x%3): %4 pixels compared, %5 differ (%6%).</source>
        <translation>%1 contra a nossa renderização (%2x%3): %4 pixels comparados, %5 diferem (%6%).</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="530"/>
        <source>Their image is unlit: one colour %1 wherever it covers. Only coverage is compared (our covered pixels in that colour), and only projection and scan conversion mistakes are tried.</source>
        <translation>A imagem deles não é iluminada: uma só cor %1 onde ela cobre. Só a cobertura é comparada (os nossos pixels cobertos nessa cor), e só erros de projeção e de conversão por varredura são tentados.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="539"/>
        <source>Largest difference per channel: %1.</source>
        <translation>Maior diferença por canal: %1.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="540"/>
        <source>Mean difference per channel, over the differing pixels: %1.</source>
        <translation>Diferença média por canal, nos pixels que diferem: %1.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="542"/>
        <source>Pixels covered: %1 by both, %2 only by ours (our depth buffer), %3 only by theirs (not the background).</source>
        <translation>Pixels cobertos: %1 por ambas, %2 só pela nossa (o nosso buffer de profundidade), %3 só pela deles (não o fundo).</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="562"/>
        <source>Diagnosis, each mistake applied before the next is ranked:</source>
        <translation>Diagnóstico, cada erro aplicado antes de classificar o seguinte:</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="568"/>
        <source>Removes %1% of the difference; makes %2 differing pixels match.</source>
        <translation>Remove %1% da diferença; faz %2 pixels diferentes coincidirem.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="549"/>
        <source>The scene has changed since this comparison: Compare Again compares their image with the scene shown now.</source>
        <translation>A cena mudou desde esta comparação: Comparar de novo compara a imagem deles com a cena mostrada agora.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="188"/>
        <source>Render Ours with the Fitted Lighting</source>
        <translation>Renderizar a Nossa com a Iluminação Ajustada</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="191"/>
        <source>Set the light&apos;s position, Ia, Il, kd, ks and n to the values fitted to their colours (one edit, undoable), and render ours with them</source>
        <translation>Pôr a posição da luz, Ia, Il, kd, ks e n nos valores ajustados às cores deles (uma edição, que pode ser desfeita), e renderizar a nossa com eles</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="331"/>
        <source>Comparing %1 with our render...</source>
        <translation>Comparando %1 com a nossa renderização...</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="332"/>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="334"/>
        <source>Compare with Image</source>
        <translation>Comparar com imagem</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="362"/>
        <source>The comparison with %1 was cancelled.</source>
        <translation>A comparação com %1 foi cancelada.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="477"/>
        <source>light x (view)</source>
        <translation>luz x (vista)</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="477"/>
        <source>light y (view)</source>
        <translation>luz y (vista)</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="478"/>
        <source>light z (view)</source>
        <translation>luz z (vista)</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="478"/>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="479"/>
        <source>ambient Ia*ka R</source>
        <translation>ambiente Ia*ka R</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="479"/>
        <source>ambient Ia*ka G</source>
        <translation>ambiente Ia*ka G</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="480"/>
        <source>ambient Ia*ka B</source>
        <translation>ambiente Ia*ka B</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="480"/>
        <source>diffuse Il*Od*kd R</source>
        <translation>difuso Il*Od*kd R</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="481"/>
        <source>diffuse Il*Od*kd G</source>
        <translation>difuso Il*Od*kd G</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="481"/>
        <source>diffuse Il*Od*kd B</source>
        <translation>difuso Il*Od*kd B</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="482"/>
        <source>specular Il*ks R</source>
        <translation>especular Il*ks R</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="482"/>
        <source>specular Il*ks G</source>
        <translation>especular Il*ks G</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="483"/>
        <source>specular Il*ks B</source>
        <translation>especular Il*ks B</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="535"/>
        <source>White wherever it covers is also what a lit image becomes with every colour multiplied by 255 (a colour scaled by 255 where it was already 0..255).</source>
        <translation>Branco onde quer que cubra é também o que uma imagem iluminada se torna com cada cor multiplicada por 255 (uma cor escalada por 255 onde já era 0..255).</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="556"/>
        <source>The images are the same.</source>
        <translation>As imagens são iguais.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="558"/>
        <source>Diagnosis: none of the mistakes RasterLab knows explains these differences.</source>
        <translation>Diagnóstico: nenhum dos erros que o RasterLab conhece explica estas diferenças.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="573"/>
        <source>Evidence: %1</source>
        <translation>Evidência: %1</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="574"/>
        <source>Check: %1</source>
        <translation>Verifique: %1</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="576"/>
        <source>At (%1, %2): ours %3, theirs %4</source>
        <translation>Em (%1, %2): nossa %3, deles %4</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="586"/>
        <source>Unexplained: %1% of the difference; %2 pixels still differ with every mistake above applied.</source>
        <translation>Sem explicação: %1% da diferença; %2 pixels ainda diferem com todos os erros acima aplicados.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="594"/>
        <source>None of the known mistakes explains most of this difference.</source>
        <translation>Nenhum dos erros conhecidos explica a maior parte desta diferença.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="599"/>
        <source>Lighting fitted to their colours</source>
        <translation>Iluminação ajustada às cores deles</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="601"/>
        <source>%1 pixels inside triangles, their image carried back onto ours by the move above: rms %2 with ours, %3 fitted.</source>
        <translation>%1 pixels dentro de triângulos, a imagem deles trazida de volta para a nossa pelo movimento acima: rms %2 com a nossa, %3 ajustada.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="603"/>
        <source>%1 pixels inside triangles: rms %2 with ours, %3 fitted.</source>
        <translation>%1 pixels dentro de triângulos: rms %2 com a nossa, %3 ajustada.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="610"/>
        <source>%1: theirs %2 ± %3, ours %4</source>
        <translation>%1: deles %2 ± %3, nosso %4</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="628"/>
        <source>Pick a pixel (here or on the image) to see their colour beside ours.</source>
        <translation>Escolha um pixel (aqui ou na imagem) para ver a cor deles ao lado da nossa.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="641"/>
        <source>Their image is moved (the first finding): this pixel&apos;s point of the surface is outside it.</source>
        <translation>A imagem deles está movida (o primeiro achado): o ponto da superfície deste pixel fica fora dela.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="645"/>
        <source>Their image is moved (the first finding): this pixel&apos;s point of the surface is their pixel (%1, %2).</source>
        <translation>A imagem deles está movida (o primeiro achado): o ponto da superfície deste pixel é o pixel (%1, %2) deles.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="651"/>
        <source>Pixel (%1, %2): theirs %3, ours %4.</source>
        <translation>Pixel (%1, %2): deles %3, nossa %4.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="658"/>
        <source>minus %1 in %2</source>
        <translation>menos %1 no %2</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="659"/>
        <source>plus %1 in %2</source>
        <translation>mais %1 no %2</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="662"/>
        <source>Their colour is ours.</source>
        <translation>A cor deles é a nossa.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="666"/>
        <source>Their colour is ours %1.</source>
        <translation>A cor deles é a nossa %1.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="668"/>
        <source>The scene has changed since the comparison: the lighting shown now is not the one compared.</source>
        <translation>A cena mudou desde a comparação: a iluminação mostrada agora não é a comparada.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="680"/>
        <source>No triangle of ours covers this pixel: it is the background.</source>
        <translation>Nenhum triângulo nosso cobre este pixel: é o fundo.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="684"/>
        <source>The lighting of this pixel is not known.</source>
        <translation>A iluminação deste pixel não é conhecida.</translation>
    </message>
    <message>
        <location filename="../app/window/compare_panel.cpp" line="686"/>
        <source>The terms that would have to change are worked out for the course&apos;s lighting model in flat or Phong shading; this pixel is shaded otherwise (the pixel inspector shows how).</source>
        <translation>Os termos que teriam de mudar são calculados para o modelo de iluminação do curso em sombreamento plano ou Phong; este pixel é sombreado de outro modo (o inspetor de pixel mostra como).</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="62"/>
        <source>the ambient term Ia·ka</source>
        <translation>o termo ambiente Ia·ka</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="63"/>
        <source>the diffuse term Il·Od·kd·(N·L)</source>
        <translation>o termo difuso Il·Od·kd·(N·L)</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="64"/>
        <source>the specular term Il·ks·(R·V)^n</source>
        <translation>o termo especular Il·ks·(R·V)^n</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="80"/>
        <source>• %1 is 0 in %2 here: changing it alone cannot give their colour.</source>
        <translation>• %1 é 0 no %2 aqui: mudá-lo sozinho não dá a cor deles.</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="85"/>
        <source>• %1 would have to be below 0 in %2: not this term alone.</source>
        <translation>• %1 teria de ser menor que 0 no %2: não é este termo sozinho.</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="102"/>
        <source>• %1 would have to be %2 instead of %3, × %4 per channel</source>
        <translation>• %1 teria de ser %2 em vez de %3, × %4 por canal</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="105"/>
        <source>: the term left out</source>
        <translation>: o termo omitido</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="108"/>
        <source>: that is the term times Od %1</source>
        <translation>: isto é, o termo vezes Od %1</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="111"/>
        <source>: that is the term without Od %1</source>
        <translation>: isto é, o termo sem Od %1</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="117"/>
        <source>(%1: 255 in both images, clamped; any value at least as high gives it.)</source>
        <translation>(%1: 255 nas duas imagens, limitado; qualquer valor pelo menos tão alto o dá.)</translation>
    </message>
    <message>
        <location filename="../views/their_colour.cpp" line="120"/>
        <source>No term changed by a simple factor (left out, times Od, without Od) gives their colour: look at several terms, or at what the diagnosis says.</source>
        <translation>Nenhum termo mudado por um fator simples (omitido, vezes Od, sem Od) dá a cor deles: olhe vários termos, ou o que diz o diagnóstico.</translation>
    </message>
</context>
<context>
    <name>rasterlab::EditPanel</name>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="218"/>
        <source>One kd for the three channels (the UFPE files have one number): changing one changes all three</source>
        <translation>Um só kd para os três canais (os arquivos da UFPE têm um só número): mudar um muda os três</translation>
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
        <translation>Câmera</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="264"/>
        <source>C: the camera&apos;s position (world)</source>
        <translation>C: a posição da câmera (mundo)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="267"/>
        <source>N: the view direction (normalised by the camera basis)</source>
        <translation>N: a direção de visão (normalizada pela base da câmera)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="269"/>
        <source>V: the up vector (made orthogonal to N by Gram-Schmidt)</source>
        <translation>V: o vetor para cima (tornado ortogonal a N por Gram-Schmidt)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="271"/>
        <source>d: the distance from C to the projection plane</source>
        <translation>d: a distância de C ao plano de projeção</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="273"/>
        <source>hx: half the width of the window on the projection plane</source>
        <translation>hx: metade da largura da janela no plano de projeção</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="275"/>
        <source>hy: half the height of the window on the projection plane</source>
        <translation>hy: metade da altura da janela no plano de projeção</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="279"/>
        <source>Light</source>
        <translation>Luz</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="282"/>
        <source>The light whose values are shown</source>
        <translation>A luz cujos valores são mostrados</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="288"/>
        <source>Add a light: a copy of the light shown</source>
        <translation>Adiciona uma luz: uma cópia da luz mostrada</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="293"/>
        <source>Remove the light shown (the scene keeps one light at least)</source>
        <translation>Remove a luz mostrada (a cena mantém pelo menos uma luz)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="302"/>
        <source>Pl: the light&apos;s position (world), or the direction toward it for a directional light</source>
        <translation>Pl: a posição da luz (mundo), ou a direção até ela, no caso de uma luz direcional</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="305"/>
        <source>Directional (w = 0)</source>
        <translation>Direcional (w = 0)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="306"/>
        <source>A directional light is infinitely far: L is the same everywhere and it is not attenuated</source>
        <translation>Uma luz direcional está infinitamente distante: L é o mesmo em todo lugar e ela não é atenuada</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="310"/>
        <source>Il: the light&apos;s colour, 0 to 255 per channel</source>
        <translation>Il: a cor da luz, de 0 a 255 por canal</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="314"/>
        <source>att</source>
        <translation>att</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="315"/>
        <source>Attenuation: the light&apos;s diffuse and specular terms are divided by kc + kl d + kq d², d its distance to the point (1 0 0: none)</source>
        <translation>Atenuação: os termos difuso e especular da luz são divididos por kc + kl d + kq d², sendo d a sua distância ao ponto (1 0 0: nenhuma)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="318"/>
        <source>Spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="319"/>
        <source>A spot lights only the points within its cutoff angle of its direction</source>
        <translation>Um spot ilumina só os pontos que estão dentro do seu ângulo de corte em torno da sua direção</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="322"/>
        <source>D: the direction the spot points to (world)</source>
        <translation>D: a direção para onde o spot aponta (mundo)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="323"/>
        <source>cut</source>
        <translation>corte</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="324"/>
        <source>The spot&apos;s cutoff angle, 0 to 90 degrees</source>
        <translation>O ângulo de corte do spot, de 0 a 90 graus</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="325"/>
        <source>exp</source>
        <translation>exp</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="326"/>
        <source>The spot&apos;s exponent: its light falls off as (-L.D)^exp toward the edge</source>
        <translation>O expoente do spot: sua luz diminui como (-L.D)^exp em direção à borda</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="330"/>
        <source>Ambient</source>
        <translation>Ambiente</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="333"/>
        <source>Ia: the ambient light&apos;s colour, 0 to 255 per channel</source>
        <translation>Ia: a cor da luz ambiente, de 0 a 255 por canal</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="335"/>
        <source>ka: the ambient coefficient, 0 to 1</source>
        <translation>ka: o coeficiente ambiente, de 0 a 1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="338"/>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="341"/>
        <source>kd: the diffuse coefficient of each channel, 0 to 1</source>
        <translation>kd: o coeficiente difuso de cada canal, de 0 a 1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="344"/>
        <source>Od: the object&apos;s diffuse colour, 0 to 1 per channel</source>
        <translation>Od: a cor difusa do objeto, de 0 a 1 por canal</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="346"/>
        <source>Ke: the light the object gives off by itself, 0 to 255 per channel (added to every lit point)</source>
        <translation>Ke: a luz que o objeto emite por si mesmo, de 0 a 255 por canal (somada a todo ponto iluminado)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="350"/>
        <source>ks: the specular coefficient, 0 to 1</source>
        <translation>ks: o coeficiente especular, de 0 a 1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="352"/>
        <source>n: the specular exponent (larger: a smaller, sharper highlight)</source>
        <translation>n: o expoente especular (maior: um brilho menor e mais nítido)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="356"/>
        <source>Shading</source>
        <translation>Sombreamento</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="359"/>
        <source>Phong (per pixel)</source>
        <translation>Phong (por pixel)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="360"/>
        <source>Gouraud (per vertex)</source>
        <translation>Gouraud (por vértice)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="361"/>
        <source>Flat (per triangle)</source>
        <translation>Plano (uma cor por triângulo)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="362"/>
        <source>Painter&apos;s algorithm (flat, no depth test)</source>
        <translation>Algoritmo do pintor (plano, sem teste de profundidade)</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="372"/>
        <source>Two-sided lighting</source>
        <translation>Iluminação dos dois lados</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="373"/>
        <source>On (the course&apos;s rule): where V.N &lt; 0 the normal is turned round, so the back of a surface is lit like its front. Off: one-sided, the back keeps a normal pointing away</source>
        <translation>Ligada (a regra do curso): onde V.N &lt; 0 a normal é invertida, então o verso de uma superfície é iluminado como a frente. Desligada: um lado só, o verso mantém uma normal que aponta para longe</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="376"/>
        <source>Blinn-Phong highlight</source>
        <translation>Brilho de Blinn-Phong</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="377"/>
        <source>The highlight with the half vector H = (L + V)/|L + V| instead of Phong&apos;s reflection R: (N.H)^n instead of (R.V)^n</source>
        <translation>O brilho com o vetor médio H = (L + V)/|L + V| em vez da reflexão R de Phong: (N.H)^n em vez de (R.V)^n</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="441"/>
        <source>Add light %1</source>
        <translation>adição da luz %1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="448"/>
        <source>Remove light %1</source>
        <translation>remoção da luz %1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="473"/>
        <source>&amp;Undo</source>
        <translation>&amp;Desfazer</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="476"/>
        <source>&amp;Redo</source>
        <translation>&amp;Refazer</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="480"/>
        <source>&amp;Save Camera and Lighting</source>
        <translation>&amp;Salvar câmera e iluminação</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="483"/>
        <source>Write the edited camera and lighting to their files</source>
        <translation>Grava a câmera e a iluminação editadas nos seus arquivos</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="489"/>
        <source>&amp;Camera...</source>
        <translation>&amp;Câmera...</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="491"/>
        <source>&amp;Lighting...</source>
        <translation>&amp;Iluminação...</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="494"/>
        <source>Save &amp;As</source>
        <translation>Sal&amp;var como</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="543"/>
        <source>Light %1 of %2</source>
        <translation>Luz %1 de %2</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="626"/>
        <source>Change %1</source>
        <translation>alteração de %1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="707"/>
        <source>A command file is shown: its scene is not edited here.</source>
        <translation>Um arquivo de comandos está aberto: sua cena não é editada aqui.</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="713"/>
        <source>%1 of the %2 example</source>
        <translation>%1 do exemplo %2</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="717"/>
        <source>built-in scene</source>
        <translation>cena embutida</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="721"/>
        <source>modified</source>
        <translation>modificada</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="727"/>
        <source>Lighting</source>
        <translation>Iluminação</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="737"/>
        <source>shading</source>
        <translation>sombreamento</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="739"/>
        <source>two-sided lighting</source>
        <translation>iluminação dos dois lados</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="741"/>
        <source>the highlight&apos;s model</source>
        <translation>modelo do brilho</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="743"/>
        <source>directional</source>
        <translation>direcional</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="746"/>
        <source>spot cutoff</source>
        <translation>corte do spot</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="749"/>
        <source>spot exponent</source>
        <translation>expoente do spot</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="752"/>
        <source>spot direction</source>
        <translation>direção do spot</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="755"/>
        <source>attenuation</source>
        <translation>atenuação</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="765"/>
        <source>%1 of light %2</source>
        <translation>%1 da luz %2</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="774"/>
        <source>The camera was not saved.</source>
        <translation>A câmera não foi salva.</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="774"/>
        <source>The lighting was not saved.</source>
        <translation>A iluminação não foi salva.</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="847"/>
        <source>the %1 example</source>
        <translation>o exemplo %1</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="852"/>
        <source>The camera has changes that are not saved (%1).</source>
        <translation>A câmera tem alterações não salvas (%1).</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="853"/>
        <source>The lighting has changes that are not saved (%1).</source>
        <translation>A iluminação tem alterações não salvas (%1).</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="773"/>
        <source>Save</source>
        <translation>Salvar</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="829"/>
        <source>Save Camera As</source>
        <translation>Salvar câmera como</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="829"/>
        <source>Save Lighting As</source>
        <translation>Salvar iluminação como</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="849"/>
        <source>the built-in scene</source>
        <translation>a cena embutida</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="851"/>
        <source>Unsaved changes</source>
        <translation>Alterações não salvas</translation>
    </message>
    <message>
        <location filename="../app/window/edit_panel.cpp" line="858"/>
        <source>Save them?</source>
        <translation>Salvá-las?</translation>
    </message>
</context>
<context>
    <name>rasterlab::Inspection</name>
    <message>
        <location filename="../views/inspection.cpp" line="191"/>
        <location filename="../views/inspection.cpp" line="193"/>
        <source>end of frame</source>
        <translation>fim do quadro</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="192"/>
        <source>start of frame: nothing drawn yet</source>
        <translation>início do quadro: nada desenhado ainda</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="197"/>
        <source>triangle %1 of %2</source>
        <translation>triângulo %1 de %2</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="200"/>
        <source>scanline %1</source>
        <translation>linha de varredura %1</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="203"/>
        <source>no pixel on it</source>
        <translation>nenhum pixel nela</translation>
    </message>
    <message>
        <location filename="../views/inspection.cpp" line="203"/>
        <source>span [%1, %2)</source>
        <translation>segmento [%1, %2)</translation>
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
        <translation>Abrir câmera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="70"/>
        <source>Open Lighting</source>
        <translation>Abrir iluminação</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="72"/>
        <source>Open Object</source>
        <translation>Abrir objeto</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="80"/>
        <source>Camera files (*.cfg *.txt);;All files (*)</source>
        <translation>Arquivos de câmera (*.cfg *.txt);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="82"/>
        <source>Lighting files (*.txt *.lux);;All files (*)</source>
        <translation>Arquivos de iluminação (*.txt *.lux);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="84"/>
        <source>Objects (*.byu *.txt);;All files (*)</source>
        <translation>Objetos (*.byu *.txt);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="31"/>
        <source>Detect from the file</source>
        <translation>Detectar pelo arquivo</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="93"/>
        <source>flat</source>
        <translation>plano</translation>
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
        <translation>plano do algoritmo do pintor</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="108"/>
        <source>%1 (built in)</source>
        <translation>%1 (embutido)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="116"/>
        <source>RasterLab</source>
        <translation>RasterLab</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="172"/>
        <source>Stopped at a breakpoint: %1</source>
        <translation>Parado num ponto de parada: %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="211"/>
        <location filename="../app/window/main_window_export.cpp" line="122"/>
        <location filename="../app/window/main_window_export.cpp" line="159"/>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="212"/>
        <source>Stop preparing the stepping of this frame</source>
        <translation>Parar a preparação do passo a passo deste quadro</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="216"/>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="274"/>
        <source>Stepping</source>
        <translation>Passo a passo</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="298"/>
        <source>Edit</source>
        <translation>Edição</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="305"/>
        <source>Breakpoints</source>
        <translation>Pontos de parada</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="311"/>
        <source>Animation</source>
        <translation>Animação</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="330"/>
        <source>1 Camera basis</source>
        <translation>1 Base da câmera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="302"/>
        <source>7 Pixel inspector (lighting)</source>
        <translation>7 Inspetor de pixel (iluminação)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="337"/>
        <source>2 View coordinates (vertices)</source>
        <translation>2 Coordenadas de vista (vértices)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="339"/>
        <source>3 Normals</source>
        <translation>3 Normais</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="341"/>
        <source>4 Projection</source>
        <translation>4 Projeção</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="333"/>
        <source>5 Scan conversion</source>
        <translation>5 Conversão por varredura</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="347"/>
        <source>5b Trapezoids</source>
        <translation>5b Trapézios</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="351"/>
        <source>6 Z-buffer</source>
        <translation>6 Z-buffer</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="48"/>
        <source>&amp;File</source>
        <translation>&amp;Arquivo</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="167"/>
        <source>&amp;Animation Frames...</source>
        <translation>&amp;Quadros da animação...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="351"/>
        <source>P&amp;ainter&apos;s algorithm (flat, far to near, no depth test)</source>
        <translation>&amp;Algoritmo do pintor (plano, do mais distante ao mais próximo, sem teste de profundidade)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1120"/>
        <source>step forward, back (on the image, or anywhere in presentation mode)</source>
        <translation>avançar, voltar um passo (na imagem, ou em qualquer lugar no modo de apresentação)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1122"/>
        <source>Space</source>
        <translation>Barra de espaço</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1122"/>
        <source>play / pause (on the image, or anywhere in presentation mode)</source>
        <translation>reproduzir / pausar (na imagem, ou em qualquer lugar no modo de apresentação)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1128"/>
        <source>let go of the picked pixel (on the image)</source>
        <translation>soltar o pixel escolhido (na imagem)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1129"/>
        <source>presentation mode on / off</source>
        <translation>ligar / desligar o modo de apresentação</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1135"/>
        <source>fill the window with the panel under the pointer (in the lecture layout, the stage&apos;s), and back</source>
        <translation>preencher a janela com o painel sob o ponteiro (no layout de aula, o da etapa), e voltar</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1139"/>
        <source>save, undo, redo</source>
        <translation>salvar, desfazer, refazer</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="57"/>
        <source>Open &amp;Camera...</source>
        <translation>Abrir &amp;câmera...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="137"/>
        <source>Draw with the Plain Divide</source>
        <translation>Desenhar com a divisão simples</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="59"/>
        <source>Ctrl+Shift+C</source>
        <translation>Ctrl+Shift+C</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="61"/>
        <source>Open &amp;Lighting...</source>
        <translation>Abrir &amp;iluminação...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="62"/>
        <source>Ctrl+Shift+L</source>
        <translation>Ctrl+Shift+L</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="64"/>
        <source>Open Command &amp;File...</source>
        <translation>Abrir arquivo de co&amp;mandos...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="65"/>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="67"/>
        <source>Open &amp;Recent</source>
        <translation>Abrir recen&amp;tes</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="69"/>
        <source>&amp;Default Scene</source>
        <translation>Cena &amp;padrão</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="107"/>
        <source>&amp;Camera</source>
        <translation>&amp;Câmera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="119"/>
        <source>&amp;Lighting</source>
        <translation>&amp;Iluminação</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="135"/>
        <source>&amp;Export PNG...</source>
        <translation>&amp;Exportar PNG...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="136"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="138"/>
        <source>Export &amp;More</source>
        <translation>E&amp;xportar mais</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="141"/>
        <source>Image as &amp;Displayed...</source>
        <translation>Imagem como &amp;exibida...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="142"/>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="144"/>
        <source>&amp;Colour Buffer at the Cursor...</source>
        <translation>Buffer de &amp;cor no cursor...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="146"/>
        <source>D&amp;epth Buffer at the Cursor...</source>
        <translation>Buffer de pro&amp;fundidade no cursor...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="148"/>
        <source>&amp;Normal Buffer...</source>
        <translation>Buffer de &amp;normais...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="149"/>
        <source>A &amp;View as Displayed</source>
        <translation>Um &amp;painel como exibido</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="153"/>
        <source>Export View</source>
        <translation>Exportar painel</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="165"/>
        <source>&amp;Stepping Sequence...</source>
        <translation>&amp;Sequência de passos...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="99"/>
        <source>&amp;Quit</source>
        <translation>Sai&amp;r</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="89"/>
        <source>Compare with &amp;Image...</source>
        <translation>Comparar com &amp;imagem...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="92"/>
        <source>A PNG of your own renderer against this scene&apos;s render, with the likely mistakes</source>
        <translation>Um PNG do seu próprio renderizador contra a renderização desta cena, com os erros prováveis</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="94"/>
        <source>Check My &amp;Renderer...</source>
        <translation>Verificar Meu &amp;Renderizador...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="96"/>
        <source>Your own renderer&apos;s stages, each held to the lecture&apos;s over the stage protocol</source>
        <translation>As etapas do seu próprio renderizador, cada uma comparada à da aula pelo protocolo de etapas</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="158"/>
        <source>Shading Side &amp;by Side...</source>
        <translation>Sombreamentos &amp;lado a lado...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="160"/>
        <source>Export Shading Side by Side</source>
        <translation>Exportar os sombreamentos lado a lado</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="172"/>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="178"/>
        <source>&amp;View</source>
        <translation>E&amp;xibir</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="182"/>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Ajustar à janela</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="186"/>
        <source>&amp;Actual Size</source>
        <translation>&amp;Tamanho real</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="188"/>
        <source>Zoom &amp;In</source>
        <translation>A&amp;umentar zoom</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="192"/>
        <source>Zoom &amp;Out</source>
        <translation>&amp;Diminuir zoom</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="202"/>
        <source>Reset &amp;Layout</source>
        <translation>Restaurar &amp;layout</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="204"/>
        <source>Fill the &amp;Window with a Panel</source>
        <translation>&amp;Preencher a janela com um painel</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="208"/>
        <source>The panel with the focus or under the mouse (the image, from the image) over the whole window; again, the layout back</source>
        <translation>O painel com o foco ou sob o mouse (a imagem, a partir da imagem) sobre a janela inteira; de novo, o layout de volta</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="216"/>
        <source>&amp;Presentation Mode</source>
        <translation>&amp;Modo de apresentação</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="221"/>
        <source>Larger text, thicker overlays, high contrast; the clicker&apos;s keys step (F5 or Esc)</source>
        <translation>Texto maior, sobreposições mais grossas, alto contraste; as teclas do passador de slides avançam os passos (F5 ou Esc)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="223"/>
        <source>&amp;Lecture Layout</source>
        <translation>Layout de &amp;aula</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="229"/>
        <source>In presentation mode, the stage being stepped fills the screen, the image beside it once something is drawn; off, your own layout (F7)</source>
        <translation>No modo de apresentação, a etapa em que se avança ocupa a tela, com a imagem ao lado assim que algo é desenhado; desligado, o seu próprio layout (F7)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="232"/>
        <source>Live &amp;Edits in Presentation</source>
        <translation>&amp;Edição ao vivo na apresentação</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="237"/>
        <source>The Edit panel stays on screen in presentation mode: the light and the material change in front of the class (F9)</source>
        <translation>O painel Edição fica na tela no modo de apresentação: a luz e o material mudam diante da turma (F9)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="251"/>
        <source>&amp;Text Size</source>
        <translation>&amp;Tamanho do texto</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="253"/>
        <source>&amp;Larger</source>
        <translation>&amp;Maior</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="256"/>
        <source>&amp;Smaller</source>
        <translation>Me&amp;nor</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="259"/>
        <source>&amp;Normal Size</source>
        <translation>Tamanho &amp;normal</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="271"/>
        <source>The System&apos;s</source>
        <translation>Do sistema</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="290"/>
        <source>S&amp;tep</source>
        <translation>&amp;Passo a passo</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="314"/>
        <source>Pick the Pixel Under the &amp;Mouse</source>
        <translation>Escolher o pixel sob o &amp;mouse</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="315"/>
        <source>Ctrl+G</source>
        <translation>Ctrl+G</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="344"/>
        <source>&amp;Shading</source>
        <translation>&amp;Sombreamento</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="348"/>
        <source>&amp;Phong (per pixel)</source>
        <translation>&amp;Phong (por pixel)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="349"/>
        <source>&amp;Gouraud (per vertex)</source>
        <translation>&amp;Gouraud (por vértice)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="350"/>
        <source>&amp;Flat (per triangle)</source>
        <translation>&amp;Plano (uma cor por triângulo)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="392"/>
        <source>Pro&amp;jection</source>
        <translation>Pro&amp;jeção</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="397"/>
        <source>&amp;Clip at the Near Plane (nothing behind the eye is divided)</source>
        <translation>&amp;Recortar no plano próximo (nada atrás do olho é dividido)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="399"/>
        <source>&amp;Plain Divide, No Clipping (seed 000 as written; seed 001&apos;s HW2)</source>
        <translation>&amp;Divisão simples, sem recorte (a seed 000 como escrita; o HW2 da seed 001)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="401"/>
        <source>&amp;Same Side (clip only triangles that cross the eye plane)</source>
        <translation>&amp;Mesmo lado (recortar só os triângulos que cruzam o plano do olho)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="709"/>
        <source>Every triangle is behind the camera (is N pointing away from the object?), so clipping at the near plane leaves nothing to draw. Seed 000&apos;s formula divides by z anyway: it would draw %1 of the %2 triangles as the object&apos;s point reflection through the eye, turned half a turn on the screen, and the z-buffer (keeping the smallest z) would keep the side farthest from the camera. The projection view&apos;s side view shows the eye, N and the object.</source>
        <translation>Todos os triângulos estão atrás da câmera (N aponta para longe do objeto?), então o recorte no plano próximo não deixa nada para desenhar. A fórmula da seed 000 divide por z mesmo assim: desenharia %1 dos %2 triângulos como a reflexão do objeto pelo olho, girada meia volta na tela, e o z-buffer (que guarda o menor z) guardaria o lado mais distante da câmera. A vista lateral da projeção mostra o olho, N e o objeto.</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1011"/>
        <source>not kept</source>
        <translation>não guardada</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1103"/>
        <source>&lt;p&gt;It follows the courses it was made for: the computer graphics course projects of UFPE and UFRPE (Phong shading with a z-buffer, and its flat-shading variant with the painter&apos;s algorithm), the assignment “HW2: 3D Rasterizer”, the per-frame rendering pipeline of an animation course, and Prof. Jonh Edson R. de Carvalho&apos;s lecture slides on illumination models (“Modelos de Iluminação”).&lt;/p&gt;</source>
        <translation>&lt;p&gt;Segue as disciplinas para as quais foi feito: os projetos da disciplina de computação gráfica da UFPE e da UFRPE (sombreamento de Phong com z-buffer, e sua variante com sombreamento plano e o algoritmo do pintor), o trabalho “HW2: 3D Rasterizer”, o pipeline de renderização por quadro de uma disciplina de animação, e os slides da aula do Prof. Jonh Edson R. de Carvalho sobre modelos de iluminação (“Modelos de Iluminação”).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1117"/>
        <source>step forward</source>
        <translation>avançar um passo</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1118"/>
        <source>step back</source>
        <translation>voltar um passo</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1121"/>
        <source>play / pause</source>
        <translation>reproduzir / pausar</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1123"/>
        <source>jump to the start / the end of the frame</source>
        <translation>ir ao início / ao fim do quadro</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1124"/>
        <source>continue to the next breakpoint</source>
        <translation>continuar até o próximo ponto de parada</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1125"/>
        <source>step by stage, triangle, scanline, span, pixel</source>
        <translation>avançar por etapa, triângulo, linha de varredura, segmento, pixel</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1126"/>
        <source>show a stage&apos;s view</source>
        <translation>mostrar o painel de uma etapa</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1127"/>
        <source>Click, arrows</source>
        <translation>Clique, setas</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1127"/>
        <source>pick a pixel, move it by one</source>
        <translation>escolher um pixel, movê-lo de um em um</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1131"/>
        <source>presentation mode: the lecture layout (the stage being stepped fills the screen) or your own layout</source>
        <translation>modo de apresentação: o layout de aula (a etapa em que se avança ocupa a tela) ou o seu próprio layout</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1133"/>
        <source>presentation mode: the Edit panel on screen (live edits)</source>
        <translation>modo de apresentação: o painel Edição na tela (edição ao vivo)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1134"/>
        <source>F11, double-click on a panel&apos;s title</source>
        <translation>F11, duplo clique no título de um painel</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1138"/>
        <source>open, export the image, export it as displayed</source>
        <translation>abrir, exportar a imagem, exportá-la como exibida</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1164"/>
        <source>Keyboard Shortcuts</source>
        <translation>Atalhos de teclado</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="369"/>
        <source>&amp;Rasterization Rules</source>
        <translation>&amp;Regras de rasterização</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="374"/>
        <source>&amp;Course (seed 000: whole-pixel vertices, screen-space interpolation)</source>
        <translation>&amp;Curso (semente 000: vértices em pixels inteiros, interpolação no espaço da tela)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="376"/>
        <source>&amp;GPU-like (1/256-pixel vertices, pixel centres, top-left rule, perspective-correct)</source>
        <translation>Como uma &amp;GPU (vértices em 1/256 de pixel, centros dos pixels, regra top-left, correção de perspectiva)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="378"/>
        <source>&amp;HW2 (seed 001&apos;s reference images)</source>
        <translation>&amp;HW2 (as imagens de referência da semente 001)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="415"/>
        <source>&amp;Help</source>
        <translation>A&amp;juda</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="421"/>
        <source>&amp;User Guide</source>
        <translation>&amp;Guia do usuário</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="427"/>
        <source>The user guide is not installed</source>
        <translation>O guia do usuário não está instalado</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="429"/>
        <source>&amp;About RasterLab</source>
        <translation>&amp;Sobre o RasterLab</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="283"/>
        <source>Messages</source>
        <translation>Mensagens</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="288"/>
        <source>Scene</source>
        <translation>Cena</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="308"/>
        <source>Accuracy</source>
        <translation>Exatidão</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="683"/>
        <location filename="../app/window/main_window_export.cpp" line="35"/>
        <location filename="../app/window/main_window_export.cpp" line="133"/>
        <location filename="../app/window/main_window_export.cpp" line="175"/>
        <location filename="../app/window/main_window_export.cpp" line="209"/>
        <source>%1: cannot export the image: %2</source>
        <translation>%1: não foi possível exportar a imagem: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="27"/>
        <source>nothing has been rendered yet</source>
        <translation>nada foi renderizado ainda</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="30"/>
        <source>Exported %1</source>
        <translation>Exportado %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="736"/>
        <source>rendering...</source>
        <translation>renderizando...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="736"/>
        <source>%1, rendering...</source>
        <translation>%1, renderizando...</translation>
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
        <translation>&amp;Abrir...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="52"/>
        <source>A course camera, lighting or object file, or a command file</source>
        <translation>Um arquivo de câmera, iluminação ou objeto do curso, ou um arquivo de comandos</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="53"/>
        <source>Open O&amp;bject...</source>
        <translation>Abrir &amp;objeto...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="55"/>
        <source>Ctrl+Shift+B</source>
        <translation>Ctrl+Shift+B</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="105"/>
        <source>Course File La&amp;youts</source>
        <translation>&amp;Formatos dos arquivos do curso</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="180"/>
        <source>Image &amp;Zoom</source>
        <translation>&amp;Zoom da imagem</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="198"/>
        <source>Pa&amp;nels</source>
        <translation>&amp;Painéis</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="213"/>
        <source>I&amp;mage</source>
        <translation>&amp;Imagem</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="266"/>
        <source>Lan&amp;guage</source>
        <translation>Idi&amp;oma</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="299"/>
        <source>Step B&amp;y</source>
        <translation>Avançar &amp;por</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="301"/>
        <source>S&amp;tage</source>
        <translation>&amp;Etapa</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_actions.cpp" line="416"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation>&amp;Atalhos de teclado</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="402"/>
        <source>Presentation mode: F5 or Esc to leave; Page Down, Right and Space step and play</source>
        <translation>Apresentação: F5 ou Esc sai; Page Down, → e Espaço avançam e reproduzem</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="666"/>
        <source>%1[*] - RasterLab</source>
        <translation>%1[*] - RasterLab</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="744"/>
        <source>Preparing the stepping of this frame</source>
        <translation>Preparando o passo a passo deste quadro</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="744"/>
        <source>Rendering</source>
        <translation>Renderizando</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="917"/>
        <source>Error: %1</source>
        <translation>Erro: %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="941"/>
        <source>Files</source>
        <translation>Arquivos</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="944"/>
        <source>Command file</source>
        <translation>Arquivo de comandos</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="945"/>
        <source>Image</source>
        <translation>Imagem</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="947"/>
        <source>%1 vertices, %2 triangles in %3 draws; %4 x %5 pixels; %6 lights</source>
        <translation>%1 vértices, %2 triângulos em %3 desenhos; %4 x %5 pixels; %6 luzes</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="957"/>
        <source>Camera</source>
        <translation>Câmera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="958"/>
        <source>Lighting</source>
        <translation>Iluminação</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="959"/>
        <source>Object</source>
        <translation>Objeto</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="961"/>
        <source>%1 vertices, %2 triangles; %3 x %4 pixels, %5 shading</source>
        <translation>%1 vértices, %2 triângulos; %3 x %4 pixels, sombreamento %5</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="268"/>
        <location filename="../app/window/main_window.cpp" line="968"/>
        <source>Stages</source>
        <translation>Etapas</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="106"/>
        <source>%1 (the %2 example)</source>
        <translation>%1 (o exemplo %2)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="301"/>
        <source>7 Pixel inspector</source>
        <translation>7 Inspetor de pixel</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="330"/>
        <source>1 Camera</source>
        <translation>1 Câmera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="333"/>
        <source>5 Scan</source>
        <translation>5 Varredura</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="336"/>
        <source>2 View</source>
        <translation>2 Vista</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="344"/>
        <source>4b Clipping</source>
        <translation>4b Recorte</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="346"/>
        <source>4b Near-plane clipping (seed 002)</source>
        <translation>4b Recorte no plano próximo (semente 002)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="349"/>
        <source>5b Trapezoids: the scan of seed 002</source>
        <translation>5b Trapézios: a varredura da semente 002</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="354"/>
        <source>Painter</source>
        <translation>Pintor</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="355"/>
        <source>Painter&apos;s algorithm (seed 004)</source>
        <translation>Algoritmo do pintor (semente 004)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="363"/>
        <source>Use the Fitted Lighting</source>
        <translation>Usar a Iluminação Ajustada</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="371"/>
        <source>Compare</source>
        <translation>Comparar</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="371"/>
        <source>Compare with their image</source>
        <translation>Comparar com a imagem deles</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="939"/>
        <source>Lesson: %1</source>
        <translation>Aula: %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="975"/>
        <source>skipped: %1</source>
        <translation>omitida: %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="978"/>
        <source>Counts</source>
        <translation>Contagens</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="979"/>
        <source>Triangles clipped at the near plane: %1; behind the camera: %2&lt;br&gt;</source>
        <translation>Triângulos recortados no plano próximo: %1; atrás da câmera: %2&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="982"/>
        <source>Zero-area triangles: %1 in view space, %2 on screen&lt;br&gt;</source>
        <translation>Triângulos de área zero: %1 no espaço de vista, %2 na tela&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="985"/>
        <source>Fragments tested: %1; written: %2; rejected: %3&lt;br&gt;</source>
        <translation>Fragmentos testados: %1; escritos: %2; rejeitados: %3&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="989"/>
        <source>Pixels shaded: %1; normals turned toward the viewer: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; clamped at 255: %5</source>
        <translation>Pixels sombreados: %1; normais voltadas para o observador: %2; N.L &amp;lt; 0: %3; R.V &amp;lt; 0: %4; limitados a 255: %5</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1013"/>
        <source>empty (+inf)</source>
        <translation>vazio (+inf)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1014"/>
        <source>x %1, y %2   RGB (%3, %4, %5)   depth %6</source>
        <translation>x %1, y %2   RGB (%3, %4, %5)   profundidade %6</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1030"/>
        <source>Open Command File</source>
        <translation>Abrir arquivo de comandos</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1031"/>
        <source>Command files (*.txt);;All files (*)</source>
        <translation>Arquivos de comandos (*.txt);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1037"/>
        <source>Open</source>
        <translation>Abrir</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1037"/>
        <source>Scene files (*.byu *.cfg *.txt *.lux);;All files (*)</source>
        <translation>Arquivos de cena (*.byu *.cfg *.txt *.lux);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1047"/>
        <source>Export PNG</source>
        <translation>Exportar PNG</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1047"/>
        <location filename="../app/window/main_window_actions.cpp" line="154"/>
        <location filename="../app/window/main_window_actions.cpp" line="161"/>
        <location filename="../app/window/main_window_export.cpp" line="198"/>
        <location filename="../app/window/main_window_export.cpp" line="206"/>
        <source>PNG images (*.png)</source>
        <translation>Imagens PNG (*.png)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1052"/>
        <source>Compare with Image</source>
        <translation>Comparar com imagem</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1053"/>
        <source>PNG images (*.png);;All files (*)</source>
        <translation>Imagens PNG (*.png);;Todos os arquivos (*)</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/window/main_window.cpp" line="1082"/>
        <source>Compared %1 with our render: %n pixel(s) differ</source>
        <translation>
            <numerusform>%1 comparada com a nossa renderização: %n pixel difere</numerusform>
            <numerusform>%1 comparada com a nossa renderização: %n pixels diferem</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1090"/>
        <source>About RasterLab</source>
        <translation>Sobre o RasterLab</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1096"/>
        <source>Released under the MIT License, whose text is in %1.</source>
        <translation>Distribuído sob a Licença MIT, cujo texto está em %1.</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1098"/>
        <source>Released under the MIT License.</source>
        <translation>Distribuído sob a Licença MIT.</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1099"/>
        <source>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;The classic software rasterization pipeline, stage by stage: camera basis, view transform, normals, projection, scan conversion, depth test and shading.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;RasterLab %1&lt;/h3&gt;&lt;p&gt;O pipeline clássico de rasterização por software, etapa por etapa: base da câmera, coordenadas de vista, normais, projeção, conversão por varredura, teste de profundidade e sombreamento.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1141"/>
        <source>the panels&apos; text larger, smaller, its normal size</source>
        <translation>o texto dos painéis maior, menor, no tamanho normal</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1143"/>
        <source>the image: zoom in, zoom out, fit, actual size (and the wheel)</source>
        <translation>a imagem: aproximar, afastar, ajustar, tamanho real (e a roda do mouse)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window.cpp" line="1156"/>
        <source>These keys act wherever the focus is, a number box included (it keeps its digits and its up and down arrows).</source>
        <translation>Estas teclas agem onde quer que esteja o foco, inclusive numa caixa de número (ela fica com os seus dígitos e as suas setas para cima e para baixo).</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="42"/>
        <source>%1: cannot export the depth buffer: %2</source>
        <translation>%1: não foi possível exportar o buffer de profundidade: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="47"/>
        <source>%1: cannot export the normal buffer: %2</source>
        <translation>%1: não foi possível exportar o buffer de normais: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="63"/>
        <source>%1: cannot export the shadings side by side: %2</source>
        <translation>%1: não é possível exportar os sombreamentos lado a lado: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="65"/>
        <source>it needs a course scene</source>
        <translation>é preciso uma cena do curso</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="70"/>
        <source>Flat</source>
        <translation>Plano</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="104"/>
        <source>%1: cannot export the view: there is no view %2</source>
        <translation>%1: não foi possível exportar o painel: não há painel %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="107"/>
        <source>%1: cannot export the view: %2</source>
        <translation>%1: não foi possível exportar o painel: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="113"/>
        <source>%1: cannot export the steps: the frame cannot be stepped through yet</source>
        <translation>%1: não foi possível exportar os passos: o quadro ainda não pode ser percorrido passo a passo</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="117"/>
        <location filename="../app/window/main_window_export.cpp" line="151"/>
        <source>%1: cannot create the folder</source>
        <translation>%1: não foi possível criar a pasta</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="122"/>
        <source>Exporting the steps...</source>
        <translation>Exportando os passos...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="144"/>
        <source>Exported %1 images to %2</source>
        <translation>%1 imagens exportadas para %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="159"/>
        <source>Exporting the animation&apos;s frames...</source>
        <translation>Exportando os quadros da animação...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="184"/>
        <source>%1: cannot render the frame: %2</source>
        <translation>%1: não foi possível renderizar o quadro: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="185"/>
        <source>Exported %1 frames to %2</source>
        <translation>%1 quadros exportados para %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="191"/>
        <source>Folder for the Animation&apos;s Frames</source>
        <translation>Pasta para os quadros da animação</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="196"/>
        <source>Export the Image as Displayed</source>
        <translation>Exportar a imagem como exibida</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="205"/>
        <source>Export a Buffer</source>
        <translation>Exportar um buffer</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="219"/>
        <source>Folder for the Numbered Images</source>
        <translation>Pasta para as imagens numeradas</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="223"/>
        <source>Stepping Sequence</source>
        <translation>Sequência de passos</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_export.cpp" line="224"/>
        <source>At most how many images (one per step, at the current granularity)?</source>
        <translation>No máximo quantas imagens (uma por passo, na granularidade atual)?</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_files.cpp" line="118"/>
        <source>%1: no course camera, lighting, object or command file in this folder</source>
        <translation>%1: nenhum arquivo de câmera, iluminação, objeto ou comandos do curso nesta pasta</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_files.cpp" line="122"/>
        <source>%1: no such file</source>
        <translation>%1: arquivo inexistente</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_files.cpp" line="140"/>
        <source>%1: not a course camera, lighting or object file, nor a command file (expected a .byu object, a camera or lighting in one of the course layouts, or png/xyz/tri commands)</source>
        <translation>%1: não é um arquivo de câmera, iluminação ou objeto do curso, nem um arquivo de comandos (esperava-se um objeto .byu, uma câmera ou iluminação num dos formatos do curso, ou comandos png/xyz/tri)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_files.cpp" line="180"/>
        <source>&amp;Clear the List</source>
        <translation>&amp;Limpar a lista</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_files.cpp" line="251"/>
        <source>%1 changed on disk: read again</source>
        <translation>%1 mudou no disco: lido de novo</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_docks.cpp" line="205"/>
        <source>%1 fills the window: F11 or a double-click on its title gives the layout back</source>
        <translation>%1 preenche a janela: F11 ou um duplo clique no seu título devolve o layout</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_docks.cpp" line="206"/>
        <source>The image</source>
        <translation>A imagem</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="80"/>
        <source>E&amp;xamples</source>
        <translation>E&amp;xemplos</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="90"/>
        <source>Open Lesso&amp;n...</source>
        <translation>Abrir a&amp;ula...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="91"/>
        <source>Ctrl+Alt+O</source>
        <translation>Ctrl+Alt+O</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="93"/>
        <source>A lesson file (.rasterlab): a scene with its stepping, picked pixel, breakpoints, zoom and docks</source>
        <translation>Um arquivo de aula (.rasterlab): uma cena com o seu passo a passo, o pixel escolhido, os pontos de parada, o zoom e os painéis</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="95"/>
        <source>Save Lesson &amp;As...</source>
        <translation>Salvar aula c&amp;omo...</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="96"/>
        <source>Ctrl+Alt+S</source>
        <translation>Ctrl+Alt+S</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="98"/>
        <source>Recent Lesso&amp;ns</source>
        <translation>Aulas rece&amp;ntes</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="124"/>
        <source>Open Lesson</source>
        <translation>Abrir aula</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="125"/>
        <source>Lessons (*.rasterlab);;All files (*)</source>
        <translation>Aulas (*.rasterlab);;Todos os arquivos (*)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="130"/>
        <source>Save Lesson</source>
        <translation>Salvar aula</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="131"/>
        <source>Lessons (*.rasterlab)</source>
        <translation>Aulas (*.rasterlab)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="134"/>
        <source>Saved the lesson to %1</source>
        <translation>A aula foi salva em %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="139"/>
        <location filename="../app/window/main_window_lessons.cpp" line="152"/>
        <source>there is no example named &apos;%1&apos; (examples: %2)</source>
        <translation>não há exemplo chamado &apos;%1&apos; (exemplos: %2)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="167"/>
        <source>the %1 was not restored, the one shown stays: %2</source>
        <translation>não foi possível restaurar %1, continua o que era mostrado: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="170"/>
        <source>camera</source>
        <translation>a câmera</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="171"/>
        <source>lighting</source>
        <translation>a iluminação</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="172"/>
        <source>object</source>
        <translation>o objeto</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="175"/>
        <source>the command file was not restored, the scene shown stays: %1</source>
        <translation>o arquivo de comandos não foi restaurado, a cena mostrada continua: %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="224"/>
        <source>The lesson opened, but not all of it: see the Messages dock</source>
        <translation>A aula abriu, mas não inteira: veja o painel Mensagens</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lessons.cpp" line="374"/>
        <source>%1: cannot save the lesson: %2</source>
        <translation>%1: não é possível salvar a aula: %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_check.cpp" line="20"/>
        <source>Check</source>
        <translation>Verificar</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_check.cpp" line="21"/>
        <source>Check your renderer</source>
        <translation>Verifique o seu renderizador</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_check.cpp" line="29"/>
        <source>Cannot write their frame to %1</source>
        <translation>Não é possível gravar o quadro deles em %1</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="160"/>
        <source>Lecture layout: the stage being stepped fills the screen (F7: your own layout)</source>
        <translation>Layout de aula: a etapa em que se avança ocupa a tela (F7: o seu próprio layout)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="162"/>
        <source>Your own layout (F7: the lecture layout again)</source>
        <translation>O seu próprio layout (F7: o layout de aula de novo)</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="280"/>
        <source>|N| = %1 · U = %2 · V = %3 · N = %4</source>
        <translation>|N| = %1 · U = %2 · V = %3 · N = %4</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="285"/>
        <source>%1 vertices: %2 in front of the camera, %3 behind</source>
        <translation>%1 vértices: %2 à frente da câmera, %3 atrás</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="294"/>
        <source>%1 triangle normals: %2 front faces, %3 back faces · %4 vertex normals</source>
        <translation>%1 normais de triângulo: %2 faces da frente, %3 faces de trás · %4 normais de vértice</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="303"/>
        <source> · triangle %1: n = %2</source>
        <translation> · triângulo %1: n = %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="309"/>
        <source>%1 triangles: %2 inside, %3 clipped, %4 behind · near plane w = %5</source>
        <translation>%1 triângulos: %2 dentro, %3 recortados, %4 atrás · plano próximo w = %5</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="315"/>
        <source>%1 triangles → %2 spans, %3 pixels covered</source>
        <translation>%1 triângulos → %2 segmentos, %3 pixels cobertos</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="320"/>
        <source>%1 fragments tested, %2 written, %3 rejected</source>
        <translation>%1 fragmentos testados, %2 escritos, %3 rejeitados</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="324"/>
        <source> · z kept from %1 to %2</source>
        <translation> · z guardado de %1 a %2</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="328"/>
        <source>%1 pixels shaded · N·L &lt; 0: %2 · R·V &lt; 0: %3 · clamped at 255: %4</source>
        <translation>%1 pixels sombreados · N·L &lt; 0: %2 · R·V &lt; 0: %3 · limitados a 255: %4</translation>
    </message>
    <message>
        <location filename="../app/window/main_window_lecture.cpp" line="398"/>
        <source>Text size %1 %</source>
        <translation>Tamanho do texto %1 %</translation>
    </message>
</context>
<context>
    <name>rasterlab::NearClipView</name>
    <message>
        <location filename="../views/near_clip_view.cpp" line="77"/>
        <source>wholly in front</source>
        <translation>inteiramente à frente</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="79"/>
        <source>clipped</source>
        <translation>recortado</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="81"/>
        <source>wholly behind</source>
        <translation>inteiramente atrás</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="83"/>
        <source>outside a clip plane</source>
        <translation>fora de um plano de recorte</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="85"/>
        <source>culled</source>
        <translation>descartado</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="87"/>
        <source>hidden back face</source>
        <translation>face traseira oculta</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="89"/>
        <source>beyond the guard band</source>
        <translation>além da banda de guarda</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="91"/>
        <source>not finite</source>
        <translation>não finito</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="207"/>
        <source>No triangle to show: select one, step into the frame, or choose one in the list.</source>
        <translation>Nenhum triângulo para mostrar: selecione um, avance pelo quadro ou escolha um na lista.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="267"/>
        <source>side view: w across (view z for the course camera), view %1 up</source>
        <translation>vista lateral: w na horizontal (o z de vista, para a câmera do curso), %1 de vista para cima</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="394"/>
        <source>w = near = %1</source>
        <translation>w = near = %1</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="397"/>
        <source>the plane w = near = %1 is far to the left, out of the picture</source>
        <translation>o plano w = near = %1 está bem à esquerda, fora da figura</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="404"/>
        <source>eye</source>
        <translation>olho</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="407"/>
        <source>the eye (w = 0) is far to the left, out of the picture</source>
        <translation>o olho (w = 0) está bem à esquerda, fora da figura</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="415"/>
        <source>on the screen (pixels)</source>
        <translation>na tela (pixels)</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="419"/>
        <source>The last step projects the triangles drawn.</source>
        <translation>O último passo projeta os triângulos desenhados.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="465"/>
        <source>zoomed: x %1 to %2, y %3 to %4</source>
        <translation>ampliado: x de %1 a %2, y de %3 a %4</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="498"/>
        <source>image %1 × %2</source>
        <translation>imagem %1 × %2</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="503"/>
        <source>Nothing drawn.</source>
        <translation>Nada desenhado.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="511"/>
        <source>The triangle shown: the one selected, or one the near plane cut</source>
        <translation>O triângulo mostrado: o selecionado, ou um que o plano próximo cortou</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="514"/>
        <source>y up</source>
        <translation>y para cima</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="515"/>
        <source>x up</source>
        <translation>x para cima</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="516"/>
        <source>Which view axis the side view draws upward</source>
        <translation>Qual eixo de vista a vista lateral desenha para cima</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="517"/>
        <source>Back</source>
        <translation>Voltar</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="519"/>
        <source>Next</source>
        <translation>Avançar</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="521"/>
        <source>All</source>
        <translation>Todos</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="587"/>
        <source>The triangle selected (or being drawn)</source>
        <translation>O triângulo selecionado (ou em desenho)</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="595"/>
        <source>triangle %1: %2</source>
        <translation>triângulo %1: %2</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="689"/>
        <source>step %1 of %2</source>
        <translation>passo %1 de %2</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="699"/>
        <source>No frame yet.</source>
        <translation>Nenhum quadro ainda.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="700"/>
        <source>No triangle to show: select one or step into the frame.</source>
        <translation>Nenhum triângulo para mostrar: selecione um ou avance pelo quadro.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="702"/>
        <source>&lt;b&gt;Triangle %1&lt;/b&gt; of %2: %3</source>
        <translation>&lt;b&gt;Triângulo %1&lt;/b&gt; de %2: %3</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="729"/>
        <source>The seed clips each triangle against the plane z = &amp;minus;&amp;epsilon;, P = [0, 0, &amp;minus;1, &amp;epsilon;], before the perspective divide (OpenGL&apos;s camera looks along &amp;minus;z). The projection stage clips against w = near in clip space, here near = %1, so P = %2 and a point A is kept when dot(P, A) = w &amp;minus; near &amp;ge; 0.</source>
        <translation>A semente recorta cada triângulo contra o plano z = &amp;minus;&amp;epsilon;, P = [0, 0, &amp;minus;1, &amp;epsilon;], antes da divisão perspectiva (a câmera do OpenGL olha ao longo de &amp;minus;z). A etapa de projeção recorta contra w = near no espaço de recorte, aqui near = %1, então P = %2 e um ponto A é mantido quando dot(P, A) = w &amp;minus; near &amp;ge; 0.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="736"/>
        <source>For the course camera w is the view z: the camera looks along +z, and the plane is z = near, P = [0, 0, 1, &amp;minus;near].</source>
        <translation>Para a câmera do curso, w é o z de vista: a câmera olha ao longo de +z, e o plano é z = near, P = [0, 0, 1, &amp;minus;near].</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="739"/>
        <source>(Written out, the seed&apos;s P keeps z &amp;le; &amp;epsilon;; the plane z = &amp;minus;&amp;epsilon; it names is P = [0, 0, &amp;minus;1, &amp;minus;&amp;epsilon;]. Either way the plane lies a little in front of the eye, so no vertex drawn is divided by w = 0.)</source>
        <translation>(Fazendo as contas, o P da semente mantém z &amp;le; &amp;epsilon;; o plano z = &amp;minus;&amp;epsilon; que ela cita é P = [0, 0, &amp;minus;1, &amp;minus;&amp;epsilon;]. De todo modo, o plano fica um pouco à frente do olho, então nenhum vértice desenhado é dividido por w = 0.)</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="743"/>
        <source>A0 = %1, A1 = %2, A2 = %3 (view space).</source>
        <translation>A0 = %1, A1 = %2, A2 = %3 (espaço de vista).</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="747"/>
        <source>This scene does not clip against the near plane (the naive or same-side projection): the steps show what clipping would do.</source>
        <translation>Esta cena não recorta contra o plano próximo (a projeção ingênua ou a do mesmo lado): os passos mostram o que o recorte faria.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="752"/>
        <source>The draw&apos;s clip planes cut the triangle first; the polygon the stage drew may differ from the one here.</source>
        <translation>Os planos de recorte do desenho cortam o triângulo primeiro; o polígono que a etapa desenhou pode diferir do mostrado aqui.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="759"/>
        <source>Vertex %1: dot(P, %1) = %2</source>
        <translation>Vértice %1: dot(P, %1) = %2</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="762"/>
        <source>kept, added to the output polygon as q%1.</source>
        <translation>mantido, acrescentado ao polígono de saída como q%1.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="764"/>
        <source>behind the plane, left out.</source>
        <translation>atrás do plano, deixado de fora.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="768"/>
        <source>Edge %1&amp;ndash;%2: dot(P, %1) = %3 and dot(P, %2) = %4 have the same sign: the edge does not cross the plane.</source>
        <translation>Aresta %1&amp;ndash;%2: dot(P, %1) = %3 e dot(P, %2) = %4 têm o mesmo sinal: a aresta não cruza o plano.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="772"/>
        <source>Edge %1&amp;ndash;%2: dot(P, %1) = %3 and dot(P, %2) = %4 differ in sign: t = (0 &amp;minus; %5) / (%6 &amp;minus; %5) = %7, C = lerp(t, %1, %2) = %8, added as q%9.</source>
        <translation>Aresta %1&amp;ndash;%2: dot(P, %1) = %3 e dot(P, %2) = %4 têm sinais opostos: t = (0 &amp;minus; %5) / (%6 &amp;minus; %5) = %7, C = lerp(t, %1, %2) = %8, acrescentado como q%9.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="780"/>
        <source>(The stage computes the same point from %1, the end in front, with t&apos; = 1 &amp;minus; t = %2, so that the two triangles sharing the edge get it bit for bit.)</source>
        <translation>(A etapa calcula o mesmo ponto a partir de %1, a ponta que está à frente, com t&apos; = 1 &amp;minus; t = %2, para que os dois triângulos que compartilham a aresta obtenham exatamente o mesmo ponto, bit a bit.)</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="791"/>
        <source>Output polygon: empty. The triangle lies wholly behind the plane: nothing is drawn.</source>
        <translation>Polígono de saída: vazio. O triângulo fica inteiramente atrás do plano: nada é desenhado.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="797"/>
        <source>Output polygon, %1 vertices: %2.</source>
        <translation>Polígono de saída, %1 vértices: %2.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="801"/>
        <source>The triangle is wholly in front: untouched.</source>
        <translation>O triângulo está inteiramente à frente: fica intacto.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="808"/>
        <source>Four vertices: split along the diagonal q0&amp;ndash;q2 into the triangles q0 q1 q2 and q0 q2 q3, rendered separately.</source>
        <translation>Quatro vértices: dividido ao longo da diagonal q0&amp;ndash;q2 nos triângulos q0 q1 q2 e q0 q2 q3, renderizados separadamente.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="811"/>
        <source>Three vertices: one triangle, nothing to split.</source>
        <translation>Três vértices: um triângulo, nada a dividir.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="813"/>
        <source>Fewer than three vertices: no triangle.</source>
        <translation>Menos de três vértices: nenhum triângulo.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="816"/>
        <source>Then each vertex is projected and taken to pixels.</source>
        <translation>Depois, cada vértice é projetado e levado a pixels.</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="819"/>
        <source>Nothing was drawn from this triangle (%1).</source>
        <translation>Nada foi desenhado deste triângulo (%1).</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="823"/>
        <source>Triangle %1: %2, %3, %4 (pixels)</source>
        <translation>Triângulo %1: %2, %3, %4 (pixels)</translation>
    </message>
    <message>
        <location filename="../views/near_clip_view.cpp" line="830"/>
        <source>(%1 of the %2 triangles were drawn: %3.)</source>
        <translation>(%1 dos %2 triângulos foram desenhados: %3.)</translation>
    </message>
</context>
<context>
    <name>rasterlab::NormalsView</name>
    <message>
        <location filename="../views/normals_model.cpp" line="164"/>
        <source>the draw is unlit: shading reads no normal</source>
        <translation>o desenho não é iluminado: o sombreamento não lê nenhuma normal</translation>
    </message>
    <message>
        <location filename="../views/normals_model.cpp" line="190"/>
        <source>the interpolated normal is zero</source>
        <translation>a normal interpolada é nula</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="36"/>
        <source>Triangle normals</source>
        <translation>Normais dos triângulos</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="39"/>
        <source>Vertex normals</source>
        <translation>Normais dos vértices</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="42"/>
        <source>Only on triangles that are seen</source>
        <translation>Só nos triângulos visíveis</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="45"/>
        <source>Hairs only on the triangles that hold a pixel at the end of the frame, and on their corners</source>
        <translation>Segmentos de normal só nos triângulos que ocupam um pixel no fim do quadro, e nos seus vértices</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="48"/>
        <source>Normals by M (wrong)</source>
        <translation>Normais por M (erradas)</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="51"/>
        <source>Beside each triangle normal, the model normal carried by viewFromModel itself instead of its inverse transpose: it leaves the surface under a non-uniform scale (set one in the Animation panel)</source>
        <translation>Ao lado de cada normal de triângulo, a normal do modelo levada pela própria viewFromModel em vez da sua inversa transposta: sob uma escala não uniforme, ela deixa de ser perpendicular à superfície (defina uma no painel Animação)</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="74"/>
        <source>Per pixel at the stepping cursor, the unit normal shading uses there: the vertex normals interpolated with the pixel&apos;s barycentrics and normalised (the triangle&apos;s normal for flat shading), turned toward the viewer as the course does before lighting; shown as RGB = (n + 1) / 2. Red grows to the right, green upward, blue away from the camera: turned normals face the camera, so blue is mostly below 128. Black: no triangle.</source>
        <translation>Por pixel, no cursor de passo, a normal unitária que o sombreamento usa ali: as normais dos vértices interpoladas com as coordenadas baricêntricas do pixel e normalizadas (a normal do triângulo no sombreamento plano), voltadas para o observador como o curso faz antes da iluminação; mostrada como RGB = (n + 1) / 2. O vermelho cresce para a direita, o verde para cima, o azul para longe da câmera: as normais voltadas encaram a câmera, então o azul fica quase sempre abaixo de 128. Preto: nenhum triângulo.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="89"/>
        <source>Mesh and normals</source>
        <translation>Malha e normais</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="90"/>
        <source>Normal map</source>
        <translation>Mapa de normais</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="284"/>
        <source>No frame yet.</source>
        <translation>Nenhum quadro ainda.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="290"/>
        <source>front faces %1</source>
        <translation>faces frontais %1</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="292"/>
        <location filename="../views/normals_view.cpp" line="296"/>
        <source>(%1 hidden, left out by culling)</source>
        <translation>(%1 ocultas, eliminadas pelo descarte)</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="294"/>
        <source>back faces (n · pView &amp;gt; 0) %1</source>
        <translation>faces traseiras (n · pView &amp;gt; 0) %1</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="299"/>
        <source>inconsistent winding: %1 triangles, %2 edges run the same way by two triangles</source>
        <translation>orientação inconsistente: %1 triângulos, %2 arestas percorridas no mesmo sentido por dois triângulos</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="306"/>
        <source>%1% of the pixels seen are back faces: the surface is closed and its normals point inward in view space (the course&apos;s [U; V; N] mirrors, so a file wound counter-clockwise seen from outside turns over). Shading turns every normal toward the viewer: the image does not change.</source>
        <translation>%1% dos pixels visíveis são faces traseiras: a superfície é fechada e suas normais apontam para dentro no espaço de vista (a matriz [U; V; N] do curso espelha, então um arquivo orientado no sentido anti-horário visto de fora fica invertido). O sombreamento volta toda normal para o observador: a imagem não muda.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="313"/>
        <source>No normals: %1.</source>
        <translation>Sem normais: %1.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="318"/>
        <source>triangle normals</source>
        <translation>normais dos triângulos</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="319"/>
        <source>vertex normals</source>
        <translation>normais dos vértices</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="321"/>
        <source>length L = %1 (%2% of the mesh&apos;s size)</source>
        <translation>comprimento L = %1 (%2% do tamanho da malha)</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="326"/>
        <source>triangle normals carried by M itself (wrong)</source>
        <translation>normais dos triângulos levadas pela própria M (errado)</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="329"/>
        <source>on the %1 triangles seen and their corners</source>
        <translation>nos %1 triângulos visíveis e seus vértices</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="332"/>
        <source>Large mesh: one triangle normal in %1 and one vertex normal in %2 are drawn; the selected triangle&apos;s always.</source>
        <translation>Malha grande: desenha-se uma normal de triângulo a cada %1 e uma normal de vértice a cada %2; as do triângulo selecionado, sempre.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="339"/>
        <source>One triangle in %1 of the wireframe is drawn.</source>
        <translation>Desenha-se um triângulo do aramado a cada %1.</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="356"/>
        <source>&lt;p&gt;&lt;b&gt;Normals by M, right and wrong&lt;/b&gt;: A = viewFromModel = viewFromWorld · M(t) · worldFromModel (M: the animation matrix, the identity when the animation is off). The model-space normal n = %1, det A = %2; the carried edges, made unit: e1 = A (P2 − P1) / |…| = %3, e2 = A (P3 − P1) / |…| = %4.&lt;br&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Normais por M, certo e errado&lt;/b&gt;: A = viewFromModel = viewFromWorld · M(t) · worldFromModel (M: a matriz de animação, a identidade quando a animação está desligada). A normal no espaço do modelo é n = %1, det A = %2; as arestas levadas, tornadas unitárias: e1 = A (P2 − P1) / |…| = %3, e2 = A (P3 − P1) / |…| = %4.&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="363"/>
        <source>Right: A&lt;sup&gt;−T&lt;/sup&gt; n, normalised = &lt;b&gt;%1&lt;/b&gt;; its dots with e1 and e2 are %2 and %3: perpendicular to the surface.&lt;br&gt;</source>
        <translation>Certo: A&lt;sup&gt;−T&lt;/sup&gt; n, normalizada = &lt;b&gt;%1&lt;/b&gt;; seus produtos escalares com e1 e e2 valem %2 e %3: perpendicular à superfície.&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="367"/>
        <source>Wrong: A n, normalised = &lt;b&gt;%1&lt;/b&gt;; its dots with e1 and e2 are %2 and %3: %4° off the surface&apos;s normal.&lt;/p&gt;</source>
        <translation>Errado: A n, normalizada = &lt;b&gt;%1&lt;/b&gt;; seus produtos escalares com e1 e e2 valem %2 e %3: desviada %4° da normal da superfície.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="373"/>
        <source>&lt;p&gt;Here both agree: A has no non-uniform scale. Set a scale such as (2, 1, 1) in the Animation panel to see them part.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Aqui as duas coincidem: A não tem escala não uniforme. Defina uma escala como (2, 1, 1) no painel Animação para vê-las se separarem.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="381"/>
        <source>&lt;p&gt;No frame yet.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Nenhum quadro ainda.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="386"/>
        <source>&lt;p&gt;&lt;b&gt;Stage 3, normals&lt;/b&gt;, in view space: each triangle&apos;s normal n = (P2 − P1) × (P3 − P1) / |(P2 − P1) × (P3 − P1)|, and each vertex&apos;s normal the normalised sum of the normals of the triangles around it. A triangle faces away from the camera (at the origin) when n · P1 &amp;gt; 0; the course turns such normals toward the viewer when it shades.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Etapa 3, normais&lt;/b&gt;, no espaço de vista: a normal de cada triângulo é n = (P2 − P1) × (P3 − P1) / |(P2 − P1) × (P3 − P1)|, e a normal de cada vértice é a soma normalizada das normais dos triângulos ao seu redor. Um triângulo está de costas para a câmera (na origem) quando n · P1 &amp;gt; 0; o curso volta essas normais para o observador ao sombrear.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="393"/>
        <source>&lt;p&gt;Skipped for this frame: %1.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Omitida neste quadro: %1.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="409"/>
        <source>&lt;p&gt;&lt;b&gt;Triangle %1&lt;/b&gt; (vertices %2, %3, %4):&lt;br&gt;P1 = %5, P2 = %6, P3 = %7&lt;br&gt;(P2 − P1) × (P3 − P1) = %8 × %9</source>
        <translation>&lt;p&gt;&lt;b&gt;Triângulo %1&lt;/b&gt; (vértices %2, %3, %4):&lt;br&gt;P1 = %5, P2 = %6, P3 = %7&lt;br&gt;(P2 − P1) × (P3 − P1) = %8 × %9</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="416"/>
        <source> = %1, length %2&lt;br&gt;</source>
        <translation> = %1, comprimento %2&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="421"/>
        <source>n = &lt;b&gt;%1&lt;/b&gt;; n · P1 = %2: %3&lt;/p&gt;</source>
        <translation>n = &lt;b&gt;%1&lt;/b&gt;; n · P1 = %2: %3&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="423"/>
        <source>a back face, drawn in red</source>
        <translation>uma face traseira, desenhada em vermelho</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="423"/>
        <source>a front face</source>
        <translation>uma face frontal</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="425"/>
        <source>a degenerate triangle: no normal.&lt;/p&gt;</source>
        <translation>um triângulo degenerado: sem normal.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="429"/>
        <source>&lt;p&gt;It runs an edge in the same direction as a neighbour does: the two are wound inconsistently (magenta), and one of their normals points the wrong way.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Ele percorre uma aresta no mesmo sentido que um vizinho: os dois têm orientações inconsistentes (magenta), e uma das suas normais aponta para o lado errado.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="436"/>
        <source>&lt;p&gt;Vertex normals: N1 = %1 (vertex %2), N2 = %3 (vertex %4), N3 = %5 (vertex %6)&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normais dos vértices: N1 = %1 (vértice %2), N2 = %3 (vértice %4), N3 = %5 (vértice %6)&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="444"/>
        <source>&lt;p&gt;Pick a pixel (here or in any image) to select its triangle and see its normal worked out.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Escolha um pixel (aqui ou em qualquer imagem) para selecionar seu triângulo e ver o cálculo da sua normal.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="454"/>
        <source>&lt;p&gt;&lt;b&gt;Pixel (%1, %2)&lt;/b&gt;: </source>
        <translation>&lt;p&gt;&lt;b&gt;Pixel (%1, %2)&lt;/b&gt;: </translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="456"/>
        <source>no triangle holds it at the cursor (black in the normal map).&lt;/p&gt;</source>
        <translation>nenhum triângulo o ocupa no cursor (preto no mapa de normais).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="458"/>
        <source>no normal: %1 (grey in the normal map).&lt;/p&gt;</source>
        <translation>sem normal: %1 (cinza no mapa de normais).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="461"/>
        <source>the triangle&apos;s normal (flat) %1</source>
        <translation>a normal do triângulo (plana) %1</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="463"/>
        <source>N = α N1 + β N2 + γ N3 with (α, β, γ) = %1: %2, normalised %3</source>
        <translation>N = α N1 + β N2 + γ N3 com (α, β, γ) = %1: %2, normalizada %3</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="467"/>
        <source>; V · N &amp;lt; 0, turned toward the viewer: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>; V · N &amp;lt; 0, voltada para o observador: &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="470"/>
        <source>. Colour (N + 1) / 2 = (%1, %2, %3).&lt;/p&gt;</source>
        <translation>. Cor (N + 1) / 2 = (%1, %2, %3).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="479"/>
        <source>%1 front faces · %2 back faces</source>
        <translation>%1 faces frontais · %2 faces traseiras</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="495"/>
        <source>x %1, y %2: no triangle</source>
        <translation>x %1, y %2: nenhum triângulo</translation>
    </message>
    <message>
        <location filename="../views/normals_view.cpp" line="499"/>
        <source>x %1, y %2: triangle %3, N = %4, colour (%5, %6, %7)</source>
        <translation>x %1, y %2: triângulo %3, N = %4, cor (%5, %6, %7)</translation>
    </message>
</context>
<context>
    <name>rasterlab::PainterView</name>
    <message>
        <location filename="../views/painter_view.cpp" line="73"/>
        <source>Painted</source>
        <translation>Ordem</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="75"/>
        <source>Draw</source>
        <translation>Desenho</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="77"/>
        <source>Triangle</source>
        <translation>Triângulo</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="79"/>
        <source>|b| (distance)</source>
        <translation>|b| (distância)</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="81"/>
        <source>Hidden wrongly</source>
        <translation>Ocultos por engano</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="138"/>
        <source>The triangles in the order the painter paints them: farthest barycentre first. Click a row to select its triangle.</source>
        <translation>Os triângulos na ordem em que o pintor os pinta: o baricentro mais distante primeiro. Clique numa linha para selecionar seu triângulo.</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="143"/>
        <source>Painter&apos;s image</source>
        <translation>Imagem do pintor</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="144"/>
        <source>Painted order (first blue, last red)</source>
        <translation>Ordem de pintura (primeiro azul, último vermelho)</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="149"/>
        <source>Mark ties on shared edges</source>
        <translation>Marcar empates nas arestas compartilhadas</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="152"/>
        <source>Pixels on an edge two triangles share, at the same depth: the z-buffer keeps the first drawn, the painter the last.</source>
        <translation>Pixels numa aresta que dois triângulos compartilham, na mesma profundidade: o z-buffer mantém o primeiro desenhado, o pintor o último.</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="341"/>
        <source>rank of the last triangle painted</source>
        <translation>ordem do último triângulo pintado</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="342"/>
        <source>painted far to near, no depth test</source>
        <translation>pintado do mais distante ao mais próximo, sem teste de profundidade</translation>
    </message>
    <message numerus="yes">
        <location filename="../views/painter_view.cpp" line="344"/>
        <source>Z-buffer (the same flat colours): %n pixel(s) differ</source>
        <translation>
            <numerusform>Z-buffer (as mesmas cores flat): %n pixel difere</numerusform>
            <numerusform>Z-buffer (as mesmas cores flat): %n pixels diferem</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="384"/>
        <source>No frame.</source>
        <translation>Nenhum quadro.</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="385"/>
        <source>Not worked out yet.</source>
        <translation>Ainda não calculado.</translation>
    </message>
    <message numerus="yes">
        <location filename="../views/painter_view.cpp" line="390"/>
        <source>&lt;b&gt;Painter&apos;s algorithm&lt;/b&gt; (seed 004): the %n triangle(s) are sorted by the distance |b| of their barycentre b (view space) to the camera, far to near, each lit once at b, and painted in that order &lt;i&gt;without a depth test&lt;/i&gt;: the last painted stays.</source>
        <translation>
            <numerusform>&lt;b&gt;Algoritmo do pintor&lt;/b&gt; (semente 004): o %n triângulo é ordenado pela distância |b| do seu baricentro b (espaço de vista) à câmera, do mais distante ao mais próximo, iluminado uma vez em b e pintado nessa ordem &lt;i&gt;sem teste de profundidade&lt;/i&gt;: o último pintado prevalece.</numerusform>
            <numerusform>&lt;b&gt;Algoritmo do pintor&lt;/b&gt; (semente 004): os %n triângulos são ordenados pela distância |b| do seu baricentro b (espaço de vista) à câmera, do mais distante ao mais próximo, cada um iluminado uma vez em b, e pintados nessa ordem &lt;i&gt;sem teste de profundidade&lt;/i&gt;: o último pintado prevalece.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="395"/>
        <source>The frame shown uses the z-buffer; this view renders the scene again as the painter would.</source>
        <translation>O quadro exibido usa o z-buffer; este painel renderiza a cena de novo como o pintor faria.</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="398"/>
        <source>Against the z-buffer with the same colours, %1 pixels differ: &lt;span style=&apos;color:#d00000&apos;&gt;%2 where a farther triangle was painted after a nearer one&lt;/span&gt; (the order of whole triangles is not the order of their pixels), &lt;span style=&apos;color:#b08800&apos;&gt;%3 on edges two triangles share at the same depth&lt;/span&gt; (the z-buffer keeps the first drawn, the painter the last).</source>
        <translation>Comparado ao z-buffer com as mesmas cores, %1 pixels diferem: &lt;span style=&apos;color:#d00000&apos;&gt;%2 onde um triângulo mais distante foi pintado depois de um mais próximo&lt;/span&gt; (a ordem dos triângulos inteiros não é a ordem dos seus pixels), &lt;span style=&apos;color:#b08800&apos;&gt;%3 em arestas que dois triângulos compartilham na mesma profundidade&lt;/span&gt; (o z-buffer mantém o primeiro desenhado, o pintor o último).</translation>
    </message>
    <message>
        <location filename="../views/painter_view.cpp" line="413"/>
        <source>Triangle %1: b = %2, |b| = %3, painted %4 of %5. The z-buffer shows it at %6 pixels; a triangle painted after it covers %7 of them though it is farther there; it covers %8 pixels of nearer triangles painted before it.</source>
        <translation>Triângulo %1: b = %2, |b| = %3, pintado na posição %4 de %5. O z-buffer o mostra em %6 pixels; um triângulo pintado depois dele cobre %7 desses pixels, embora ali esteja mais distante; ele cobre %8 pixels de triângulos mais próximos pintados antes dele.</translation>
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
        <translation>sem normal</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="387"/>
        <source>in the plane of N and L</source>
        <translation>no plano de N e L</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="421"/>
        <source>Step</source>
        <translation>Passo</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="421"/>
        <source>Triangle</source>
        <translation>Triângulo</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="421"/>
        <source>Depth test</source>
        <translation>Teste de profundidade</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="422"/>
        <source>Before</source>
        <translation>Antes</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="422"/>
        <source>After</source>
        <translation>Depois</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="422"/>
        <source>Result</source>
        <translation>Resultado</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="437"/>
        <source>▶ holds the pixel at the stepping cursor; grey rows are not reached yet. Select a row to see its lighting.</source>
        <translation>▶ ocupa o pixel no cursor de passo; as linhas cinza ainda não foram alcançadas. Selecione uma linha para ver sua iluminação.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="127"/>
        <source>Pick a pixel on the image to see its history.</source>
        <translation>Escolha um pixel na imagem para ver seu histórico.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="41"/>
        <source>%1 over %2</source>
        <translation>%1 sobre %2</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="42"/>
        <source>painted, no depth test</source>
        <translation>pintado, sem teste de profundidade</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="49"/>
        <source>written</source>
        <translation>escrito</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="57"/>
        <source>rejected: the depth is not a number</source>
        <translation>rejeitado: a profundidade não é um número</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="59"/>
        <source>rejected: as far, the earlier keeps it</source>
        <translation>rejeitado: mesma distância, o anterior fica</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="61"/>
        <source>rejected: farther</source>
        <translation>rejeitado: mais distante</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="64"/>
        <source>%1 outside [0, 1]</source>
        <translation>%1 fora de [0, 1]</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="65"/>
        <source>discarded: depth outside [0, 1]</source>
        <translation>descartado: profundidade fora de [0, 1]</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="86"/>
        <source>cleared to %1</source>
        <translation>limpo com %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="87"/>
        <source>the background</source>
        <translation>o fundo</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="137"/>
        <source>the final pixel</source>
        <translation>o pixel final</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="145"/>
        <source>Preparing the stepping of this frame: the pixel&apos;s history follows.</source>
        <translation>Preparando o passo a passo deste quadro: o histórico do pixel vem a seguir.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="185"/>
        <source>The frame could not be traced again: %1</source>
        <translation>Não foi possível rastrear o quadro de novo: %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="227"/>
        <source>depth %1</source>
        <translation>profundidade %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="229"/>
        <source>none</source>
        <translation>nenhum</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="230"/>
        <source>depth %1 (cleared)</source>
        <translation>profundidade %1 (valor de limpeza)</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="249"/>
        <source>Nothing drew here: the pixel keeps the background %1.</source>
        <translation>Nada foi desenhado aqui: o pixel mantém o fundo %1.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="258"/>
        <source>The only fragment was rejected: the pixel keeps the background.</source>
        <translation>O único fragmento foi rejeitado: o pixel mantém o fundo.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="259"/>
        <source>Every fragment was rejected (%1): the pixel keeps the background.</source>
        <translation>Todos os fragmentos foram rejeitados (%1): o pixel mantém o fundo.</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="263"/>
        <source>Written by triangle %1</source>
        <translation>Escrito pelo triângulo %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="265"/>
        <source>over 1 earlier write</source>
        <translation>sobre 1 escrita anterior</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="267"/>
        <source>over %1 earlier writes</source>
        <translation>sobre %1 escritas anteriores</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="269"/>
        <source>1 fragment rejected</source>
        <translation>1 fragmento rejeitado</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="271"/>
        <source>%1 fragments rejected</source>
        <translation>%1 fragmentos rejeitados</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="102"/>
        <source>black: the vertex colours mixed here are black</source>
        <translation>preto: as cores dos vértices misturadas aqui são pretas</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="104"/>
        <source>black: the object colour is black</source>
        <translation>preto: a cor do objeto é preta</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="105"/>
        <source>black: the light takes away what the ambient term adds</source>
        <translation>preto: a luz tira o que o termo ambiente acrescenta</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="106"/>
        <source>black: zero normal and no ambient</source>
        <translation>preto: normal nula e sem ambiente</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="107"/>
        <source>black: no light and no ambient</source>
        <translation>preto: sem luz e sem ambiente</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="108"/>
        <source>black: the light is at the point and no ambient</source>
        <translation>preto: a luz está no próprio ponto e sem ambiente</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="109"/>
        <source>black: N.L &lt; 0 and no ambient</source>
        <translation>preto: N.L &lt; 0 e sem ambiente</translation>
    </message>
    <message>
        <location filename="../views/pixel_history.cpp" line="110"/>
        <source>black: the diffuse and specular terms are 0 here and there is no ambient</source>
        <translation>preto: os termos difuso e especular valem 0 aqui e não há ambiente</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="389"/>
        <source>Light %1, directional toward %2 (view), Il = %3</source>
        <translation>Luz %1, direcional, na direção %2 (vista), Il = %3</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="390"/>
        <source>Light %1 at %2 (view), Il = %3</source>
        <translation>Luz %1 em %2 (vista), Il = %3</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="393"/>
        <source>  at the point itself (L = 0): nothing</source>
        <translation>  no próprio ponto (L = 0): nada</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="398"/>
        <source>att = 1 / (%1 + %2 × %3 + %4 × %3²) = %5</source>
        <translation>att = 1 / (%1 + %2 × %3 + %4 × %3²) = %5</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="402"/>
        <source>d = %1, not attenuated</source>
        <translation>d = %1, sem atenuação</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="404"/>
        <source>spot: −L.D = %1 &lt; cos %2° = %3, outside the cone: 0</source>
        <translation>spot: −L.D = %1 &lt; cos %2° = %3, fora do cone: 0</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="407"/>
        <source>spot: −L.D = %1 ≥ cos %2° = %3, %1^%4 = %5</source>
        <translation>spot: −L.D = %1 ≥ cos %2° = %3, %1^%4 = %5</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="415"/>
        <source>  N.L = %1 &lt; 0: behind the surface, nothing</source>
        <translation>  N.L = %1 &lt; 0: atrás da superfície, nada</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="417"/>
        <source>  N.L = %1, %2 = %3: diffuse %4, specular %5</source>
        <translation>  N.L = %1, %2 = %3: difusa %4, especular %5</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="133"/>
        <source>N flipped toward the viewer: V.N &lt; 0, so N := −N before lighting.</source>
        <translation>N invertida para o observador: V.N &lt; 0, então N := −N antes da iluminação.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="136"/>
        <source>Zero normal: only degenerate triangles meet here, or the vertex normals cancel out; ambient only.</source>
        <translation>Normal nula: só triângulos degenerados se encontram aqui, ou as normais dos vértices se anulam; só ambiente.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="140"/>
        <source>The light is at the point itself (L = 0): it adds nothing.</source>
        <translation>A luz está no próprio ponto (L = 0): não acrescenta nada.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="143"/>
        <source>N.L &lt; 0: the light is behind the surface; no diffuse, no specular.</source>
        <translation>N.L &lt; 0: a luz está atrás da superfície; sem difusa, sem especular.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="146"/>
        <source>R.V &lt; 0: the reflected ray points away from the viewer; no specular.</source>
        <translation>R.V &lt; 0: o raio refletido aponta para longe do observador; sem especular.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="163"/>
        <source>Outside the cone of light %1: −L.D = %2 is below cos %3° = %4; it adds nothing here.</source>
        <translation>Fora do cone da luz %1: −L.D = %2 está abaixo de cos %3° = %4; ela não acrescenta nada aqui.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="171"/>
        <source>One-sided lighting: the back of the surface is seen (V.N &lt; 0) and N is not turned toward the viewer.</source>
        <translation>Iluminação de um lado só: vê-se o verso da superfície (V.N &lt; 0) e N não é voltada para o observador.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="181"/>
        <source>Texture at (s, t) = (%1, %2): texel %3.</source>
        <translation>Textura em (s, t) = (%1, %2): texel %3.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="186"/>
        <source>Seed 001&apos;s text and its reference images disagree here: the texel nearest to (s w, t h) once the coordinates wrap is %1; the images&apos; (int)(s w + 0.5) mod w gives %2, which these rules follow.</source>
        <translation>O texto da seed 001 e as suas imagens de referência discordam aqui: o texel mais próximo de (s w, t h) depois de as coordenadas darem a volta é %1; o (int)(s w + 0.5) mod w das imagens dá %2, que estas regras seguem.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="190"/>
        <source>Seed 001&apos;s text and its reference images disagree here: the texel nearest to (s w, t h) once the coordinates wrap is %1, which these rules follow; the images&apos; (int)(s w + 0.5) mod w gives %2.</source>
        <translation>O texto da seed 001 e as suas imagens de referência discordam aqui: o texel mais próximo de (s w, t h) depois de as coordenadas darem a volta é %1, que estas regras seguem; o (int)(s w + 0.5) mod w das imagens dá %2.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="207"/>
        <source>Clamped: %1 above the colour scale %2, written as byte 255.</source>
        <translation>Limitado: %1 acima da escala de cor %2, escrito como byte 255.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="216"/>
        <source>%1 (clamped)</source>
        <translation>%1 (limitado)</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="221"/>
        <source>Gouraud shading, the vertices&apos; colours mixed</source>
        <translation>sombreamento de Gouraud, as cores dos vértices misturadas</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="222"/>
        <source>C = α C1 + β C2 + γ C3</source>
        <translation>C = α C1 + β C2 + γ C3</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="238"/>
        <source>not lit, the object colour as it is</source>
        <translation>sem iluminação, a cor do objeto tal como é</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="239"/>
        <source>I = O (the object colour)</source>
        <translation>I = O (a cor do objeto)</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="248"/>
        <source>the course&apos;s Phong lighting model</source>
        <translation>o modelo de iluminação de Phong do curso</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="249"/>
        <source>Lambert with Blinn-Phong highlights (command files)</source>
        <translation>Lambert com brilhos de Blinn-Phong (arquivos de comandos)</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="251"/>
        <source>Painter&apos;s algorithm: lit as flat shading, once at the triangle&apos;s barycentre; the triangles are painted far to near without a depth test.</source>
        <translation>Algoritmo do pintor: iluminado como no sombreamento plano, uma vez no baricentro do triângulo; os triângulos são pintados do mais distante ao mais próximo, sem teste de profundidade.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="256"/>
        <source>Flat shading: evaluated once, at the triangle&apos;s barycentre with the triangle&apos;s normal; every pixel of the triangle gets this colour.</source>
        <translation>Sombreamento flat: avaliado uma vez, no baricentro do triângulo, com a normal do triângulo; todo pixel do triângulo recebe esta cor.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="260"/>
        <source>%1 lights: the diffuse and specular terms are sums over them; the numbers filled in are the first light&apos;s.</source>
        <translation>%1 luzes: os termos difuso e especular são somas sobre elas; os números preenchidos são os da primeira luz.</translation>
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
        <translation>att = 1 / (kc + kl d + kq d²) para uma luz posicional, 1 para uma direcional; spot = (−L.D)^exp dentro do cone, 0 fora dele, 1 para uma luz que não é spot.</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="286"/>
        <source>I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n</source>
        <translation>I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="293"/>
        <source>I = Σ Il O (N.L) + Il (H.N)^s, over the lights with N.L ≥ 0</source>
        <translation>I = Σ Il O (N.L) + Il (H.N)^s, sobre as luzes com N.L ≥ 0</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="295"/>
        <source>I = Σ Il O (N.L), over the lights with N.L ≥ 0</source>
        <translation>I = Σ Il O (N.L), sobre as luzes com N.L ≥ 0</translation>
    </message>
    <message>
        <location filename="../views/lighting_breakdown.cpp" line="352"/>
        <source>%1 (the other lights)</source>
        <translation>%1 (as outras luzes)</translation>
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
        <translation>Ke = %1: a luz própria do material</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="635"/>
        <source>Your renderer&apos;s colour here: (%1, %2, %3); ours (%4, %5, %6).</source>
        <translation>A cor do seu renderizador aqui: (%1, %2, %3); a nossa (%4, %5, %6).</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="654"/>
        <source>No triangle of ours holds this pixel.</source>
        <translation>Nenhum triângulo nosso ocupa este pixel.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="657"/>
        <source>The terms are worked out for the course&apos;s lighting in flat or Phong shading only.</source>
        <translation>Os termos são calculados só para a iluminação do curso em sombreamento plano ou Phong.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="662"/>
        <source>For your colour, each term alone:</source>
        <translation>Para a sua cor, cada termo sozinho:</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="708"/>
        <source>start</source>
        <translation>início</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="714"/>
        <location filename="../views/pixel_inspector.cpp" line="915"/>
        <source>end</source>
        <translation>fim</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="722"/>
        <source>holds the pixel at the stepping cursor</source>
        <translation>ocupa o pixel no cursor de passo</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="723"/>
        <source>not reached yet by the stepping cursor</source>
        <translation>ainda não alcançado pelo cursor de passo</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="738"/>
        <source>not kept</source>
        <translation>não guardada</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="739"/>
        <source>Without stepping, the colours of writes overwritten later are not kept.</source>
        <translation>Sem o passo a passo, as cores das escritas sobrescritas depois não são guardadas.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="856"/>
        <source>Before: %1</source>
        <translation>Antes: %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="896"/>
        <source>Without stepping, only the lighting of the fragment that holds the pixel at the end is recorded.</source>
        <translation>Sem o passo a passo, só a iluminação do fragmento que ocupa o pixel no fim é registrada.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="899"/>
        <source>The cleared pixel is not lit.</source>
        <translation>O pixel limpo não é iluminado.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="902"/>
        <source>No fragment holds the pixel at the cursor: select a row of the history to see its lighting.</source>
        <translation>Nenhum fragmento ocupa o pixel no cursor: selecione uma linha do histórico para ver sua iluminação.</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="914"/>
        <source>Lighting of step %1, triangle %2: %3</source>
        <translation>Iluminação do passo %1, triângulo %2: %3</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="919"/>
        <source>(rejected: this colour was never written)</source>
        <translation>(rejeitado: esta cor nunca foi escrita)</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="932"/>
        <source>object colour</source>
        <translation>cor do objeto</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="935"/>
        <source>emission</source>
        <translation>emissão</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="937"/>
        <source>ambient</source>
        <translation>ambiente</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="942"/>
        <source>diffuse %1</source>
        <translation>difusa %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="945"/>
        <source>specular %1</source>
        <translation>especular %1</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="949"/>
        <source>diffuse</source>
        <translation>difusa</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="951"/>
        <source>specular</source>
        <translation>especular</translation>
    </message>
    <message>
        <location filename="../views/pixel_inspector.cpp" line="978"/>
        <source>No special case: every term applies as written.</source>
        <translation>Nenhum caso especial: todos os termos valem como escritos.</translation>
    </message>
</context>
<context>
    <name>rasterlab::ProjectionCanvas</name>
    <message>
        <location filename="../views/projection_view.cpp" line="161"/>
        <source>Click a triangle to select it; wheel to zoom, drag to pan, double-click to fit.</source>
        <translation>Clique num triângulo para selecioná-lo; roda para o zoom, arraste para deslocar, clique duas vezes para ajustar.</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="389"/>
        <source>No frame yet.</source>
        <translation>Nenhum quadro ainda.</translation>
    </message>
</context>
<context>
    <name>rasterlab::ProjectionSideView</name>
    <message>
        <location filename="../views/projection_view.cpp" line="615"/>
        <source>view z (= w) →</source>
        <translation>z de vista (= w) →</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="615"/>
        <source>clip w →</source>
        <translation>w de recorte →</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="619"/>
        <source>y ↑</source>
        <translation>y ↑</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="630"/>
        <source>eye plane w = 0: the plain divide clips nothing</source>
        <translation>plano do olho w = 0: a divisão simples não recorta nada</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="631"/>
        <source>near plane w = %1</source>
        <translation>plano próximo w = %1</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="634"/>
        <source>the object lies behind the eye (w &lt; 0): N points away from it</source>
        <translation>o objeto está atrás do olho (w &lt; 0): N aponta para longe dele</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="638"/>
        <source>● made by clipping: %1</source>
        <translation>● criados pelo recorte: %1</translation>
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
        <translation>Mostra os vértices em coordenadas normalizadas de dispositivo, [-1, 1]</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="683"/>
        <source>Pixels</source>
        <translation>Pixels</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="685"/>
        <source>Show the vertices in pixels, snapped as scan conversion receives them</source>
        <translation>Mostra os vértices em pixels, ajustados à grade como a conversão por varredura os recebe</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="694"/>
        <source>Fit</source>
        <translation>Ajustar</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="695"/>
        <source>Show the whole window and its margin</source>
        <translation>Mostra a janela inteira e sua margem</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="820"/>
        <source>No frame yet.</source>
        <translation>Nenhum quadro ainda.</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="825"/>
        <source>inside %1, clipped %2 (%3 on screen), culled %4, back faces %5; behind %6, clipped away %7</source>
        <translation>dentro %1, recortados %2 (%3 na tela), descartados %4, faces traseiras %5; atrás %6, eliminados no recorte %7</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="836"/>
        <source>beyond the guard band %1</source>
        <translation>além da banda de guarda %1</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="838"/>
        <source>not finite %1</source>
        <translation>não finitos %1</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="839"/>
        <source>%1 inside · %2 clipped · %3 culled · %4 behind</source>
        <translation>%1 dentro · %2 recortados · %3 descartados · %4 atrás</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="845"/>
        <source>%1 drawn whole (inside): %2&lt;br&gt;</source>
        <translation>%1 desenhados inteiros (dentro): %2&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="846"/>
        <source>%1 clipped: %2, drawn as %3 fan triangles&lt;br&gt;</source>
        <translation>%1 recortados: %2, desenhados como %3 triângulos em leque&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="850"/>
        <source>%1 culled (clockwise on screen): %2; hidden back faces: %3&lt;br&gt;</source>
        <translation>%1 descartados (sentido horário na tela): %2; faces traseiras ocultas: %3&lt;br&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="854"/>
        <source>Nothing on screen: behind the near plane %1; outside a clip plane %2</source>
        <translation>Nada na tela: atrás do plano próximo %1; fora de um plano de recorte %2</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="857"/>
        <source>; beyond the guard band %1</source>
        <translation>; além da banda de guarda %1</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="858"/>
        <source>; not finite %1</source>
        <translation>; não finitos %1</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="862"/>
        <source>%1 screen triangles go to scan conversion. The plain divide clips nothing (seed 000 as written; seed 001&apos;s HW2): %2 wholly behind the eye, drawn mirrored through the centre; %3 across the eye plane, drawn wrong.</source>
        <translation>%1 triângulos de tela vão para a conversão por varredura. A divisão simples não recorta nada (a seed 000 como escrita; o HW2 da seed 001): %2 inteiramente atrás do olho, desenhados espelhados pelo centro; %3 atravessando o plano do olho, desenhados errados.</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="870"/>
        <source>%1 screen triangles go to scan conversion; the near plane is w = %2.</source>
        <translation>%1 triângulos de tela vão para a conversão por varredura; o plano próximo é w = %2.</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="875"/>
        <source>%1 selected, %2 being drawn</source>
        <translation>%1 selecionado, %2 em desenho</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="897"/>
        <source>&lt;p&gt;&lt;b&gt;Projection.&lt;/b&gt; Every vertex goes to clip space, pClip = clipFromView · pView, and is divided by its w without any clipping, as seed 000 writes the formula and seed 001&apos;s HW2 does (&quot;frustum clipping happens here in OpenGL, but we won&apos;t add it&quot;): pNdc = pClip.xy / w. A vertex behind the eye (w &amp;lt; 0) lands mirrored through the centre; a triangle across the eye plane wraps through infinity. Clipping at the near plane (Shading &amp;gt; Projection) draws only what lies in front.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Projeção.&lt;/b&gt; Cada vértice vai para o espaço de recorte, pClip = clipFromView · pView, e é dividido pelo seu w sem recorte algum, como a seed 000 escreve a fórmula e o HW2 da seed 001 faz (&quot;o recorte pelo volume de visão (frustum) acontece aqui no OpenGL, mas não vamos adicioná-lo&quot;): pNdc = pClip.xy / w. Um vértice atrás do olho (w &amp;lt; 0) cai espelhado pelo centro; um triângulo que atravessa o plano do olho dá a volta pelo infinito. O recorte no plano próximo (Sombreamento &amp;gt; Projeção) desenha só o que está à frente.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="904"/>
        <source>&lt;p&gt;&lt;b&gt;Projection.&lt;/b&gt; Every vertex goes to clip space, pClip = clipFromView · pView. A triangle crossing the near plane w = near is clipped (Sutherland-Hodgman) and its polygon cut into a fan, so nothing is divided by a w at or behind the camera. Then pNdc = pClip.xy / w, and the pixels are x = (x_ndc + 1) W/2, y = (1 − y_ndc) H/2.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Projeção.&lt;/b&gt; Todo vértice vai para o espaço de recorte, pClip = clipFromView · pView. Um triângulo que cruza o plano próximo w = near é recortado (Sutherland-Hodgman) e seu polígono é dividido em leque, de modo que nada é dividido por um w na câmera ou atrás dela. Depois pNdc = pClip.xy / w, e os pixels são x = (x_ndc + 1) W/2, y = (1 − y_ndc) H/2.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="911"/>
        <source>&lt;p&gt;For the course camera pClip = ((d/hx) x, (d/hy) y, z, z): x_ndc = (d/hx) x/z, y_ndc = (d/hy) y/z, and the pixel coordinates are truncated.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Para a câmera do curso, pClip = ((d/hx) x, (d/hy) y, z, z): x_ndc = (d/hx) x/z, y_ndc = (d/hy) y/z, e as coordenadas de pixel são truncadas.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="919"/>
        <source>&lt;p&gt;Click a triangle to see the numbers of its first vertex.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Clique num triângulo para ver os números do seu primeiro vértice.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="939"/>
        <source>&lt;p&gt;&lt;b&gt;Triangle %1&lt;/b&gt; (mesh triangle %2%3), its first vertex, vertex %4:</source>
        <translation>&lt;p&gt;&lt;b&gt;Triângulo %1&lt;/b&gt; (triângulo %2 da malha%3), seu primeiro vértice, o vértice %4:</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="942"/>
        <source>, clipped</source>
        <translation>, recortado</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="947"/>
        <source>made by clipping, on the edge from vertex %1 to vertex %2 at t = %3</source>
        <translation>criado pelo recorte, na aresta do vértice %1 ao vértice %2, em t = %3</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="972"/>
        <source>not snapped</source>
        <translation>sem arredondamento para a grade</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="975"/>
        <source>truncated</source>
        <translation>truncado</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="975"/>
        <source>rounded</source>
        <translation>arredondado</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="978"/>
        <source>truncated to 1/%1 pixel</source>
        <translation>truncado para 1/%1 de pixel</translation>
    </message>
    <message>
        <location filename="../views/projection_view.cpp" line="979"/>
        <source>rounded to 1/%1 pixel</source>
        <translation>arredondado para 1/%1 de pixel</translation>
    </message>
</context>
<context>
    <name>rasterlab::ScanlineView</name>
    <message>
        <location filename="../views/scanline_view.cpp" line="305"/>
        <source>No triangle to show: step into the frame or pick a pixel.</source>
        <translation>Nenhum triângulo para mostrar: avance pelo quadro ou escolha um pixel.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="258"/>
        <source>long edge</source>
        <translation>aresta longa</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="258"/>
        <source>upper edge</source>
        <translation>aresta superior</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="259"/>
        <source>lower edge</source>
        <translation>aresta inferior</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="654"/>
        <source>No frame yet.</source>
        <translation>Nenhum quadro ainda.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="657"/>
        <source>Start of the frame: step forward to walk the first triangle, or pick a pixel to see the triangle holding it.</source>
        <translation>Início do quadro: avance para percorrer o primeiro triângulo, ou escolha um pixel para ver o triângulo que o ocupa.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="660"/>
        <source>Pick a pixel, or step through the frame, to see a triangle scan converted.</source>
        <translation>Escolha um pixel, ou avance pelo quadro, para ver a conversão por varredura de um triângulo.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="665"/>
        <source>&lt;b&gt;Triangle %1&lt;/b&gt; of %2</source>
        <translation>&lt;b&gt;Triângulo %1&lt;/b&gt; de %2</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="668"/>
        <source>scanline %1</source>
        <translation>linha de varredura %1</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="670"/>
        <source>pixel %1</source>
        <translation>pixel %1</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="673"/>
        <source>at the stepping cursor</source>
        <translation>no cursor de passo</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="674"/>
        <source>the triangle selected (the cursor is at the %1 of the frame)</source>
        <translation>o triângulo selecionado (o cursor está no %1 do quadro)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="675"/>
        <source>start</source>
        <translation>início</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="676"/>
        <source>end</source>
        <translation>fim</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="704"/>
        <source>Vertices sorted by y: top %1, middle %2, bottom %3. The long edge runs from the top to the bottom; the two short edges meet at the middle vertex.</source>
        <translation>Vértices ordenados por y: topo %1, meio %2, base %3. A aresta longa vai do topo à base; as duas arestas curtas se encontram no vértice do meio.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="709"/>
        <source>Its area on the screen is zero: it has no inside and is not scanned.</source>
        <translation>Sua área na tela é zero: ele não tem interior e não é varrido.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="714"/>
        <source>(s1 &amp;minus; s0) &amp;times; (s2 &amp;minus; s0) = %1, so the middle vertex is %2 of the long edge: the long edge bounds the spans on the %3.</source>
        <translation>(s1 &amp;minus; s0) &amp;times; (s2 &amp;minus; s0) = %1, então o vértice do meio fica à %2 da aresta longa: a aresta longa limita os segmentos à %3.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="717"/>
        <location filename="../views/scanline_view.cpp" line="718"/>
        <location filename="../views/scanline_view.cpp" line="778"/>
        <source>right</source>
        <translation>direita</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="717"/>
        <location filename="../views/scanline_view.cpp" line="718"/>
        <location filename="../views/scanline_view.cpp" line="778"/>
        <source>left</source>
        <translation>esquerda</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="692"/>
        <source>long</source>
        <translation>longa</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="692"/>
        <source>upper</source>
        <translation>superior</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="692"/>
        <source>lower</source>
        <translation>inferior</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="765"/>
        <source>from</source>
        <translation>de</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="766"/>
        <source>to</source>
        <translation>até</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="767"/>
        <source>x on its first row</source>
        <translation>x na sua primeira linha</translation>
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
        <translation>linhas</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="775"/>
        <location filename="../views/scanline_view.cpp" line="829"/>
        <source>none</source>
        <translation>nenhuma</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="778"/>
        <source>side</source>
        <translation>lado</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="782"/>
        <source>Only rows %1 to %2 are on the screen: the walk starts and stops there.</source>
        <translation>Só as linhas %1 a %2 estão na tela: o percurso começa e termina ali.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="724"/>
        <source>No row of this triangle is on the screen.</source>
        <translation>Nenhuma linha deste triângulo está na tela.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="267"/>
        <source>your span</source>
        <translation>seu segmento</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="268"/>
        <source>only yours</source>
        <translation>só seus</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="269"/>
        <source>only ours</source>
        <translation>só nossos</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="738"/>
        <source>Here the additions are seed 001&apos;s DDA, in double: an edge that lands a hair below a row in double leaves that row to the triangle above, where an exact walk would find the edge through the row&apos;s samples.</source>
        <translation>Aqui as somas são o DDA da semente 001, em double: uma aresta que fica um fio abaixo de uma linha em double deixa essa linha para o triângulo de cima, onde um percurso exato acharia a aresta passando pelas amostras da linha.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="829"/>
        <source>%1 to %2</source>
        <translation>%1 a %2</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="833"/>
        <source>Your renderer: no pixel on this row (ours: %1).</source>
        <translation>O seu renderizador: nenhum pixel nesta linha (o nosso: %1).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="838"/>
        <source>Your renderer: pixels %1 to %2 (ours: %3).</source>
        <translation>O seu renderizador: pixels %1 a %2 (o nosso: %3).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="859"/>
        <source>%1(%2) = %3, where the %4 edge crosses its first row</source>
        <translation>%1(%2) = %3, onde a aresta %4 cruza sua primeira linha</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="865"/>
        <source>%1(%2) = %3, where the %4 edge crosses the first row on the screen</source>
        <translation>%1(%2) = %3, onde a aresta %4 cruza a primeira linha na tela</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="873"/>
        <source>%1(%2) = %1(%3) + dx/dy = %4 + %5 = %6 along the %7 edge</source>
        <translation>%1(%2) = %1(%3) + dx/dy = %4 + %5 = %6 ao longo da aresta %7</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="888"/>
        <source>Scanline y = %1</source>
        <translation>Linha de varredura y = %1</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="890"/>
        <source>(sampled at y = %1)</source>
        <translation>(amostrada em y = %1)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="902"/>
        <source>Seed 001&apos;s DDA: x_left and x_right are sums in double, one addition of dx/dy a row, the rounding of each carried along (no snapping). Pixels x = ceil(x_left) = %1 while x &amp;lt; x_right: up to ceil(x_right) &amp;minus; 1 = %2 (a sample exactly on the right edge belongs to the next triangle).</source>
        <translation>DDA da semente 001: x_left e x_right são somas em double, uma soma de dx/dy por linha, o arredondamento de cada uma levado adiante (sem arredondar os vértices para a grade). Pixels x = ceil(x_left) = %1 enquanto x &amp;lt; x_right: até ceil(x_right) &amp;minus; 1 = %2 (uma amostra exatamente na aresta direita pertence ao triângulo seguinte).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="909"/>
        <source>Top-left rule: the samples with x_left &amp;le; x%1 &amp;lt; x_right, pixels ceil(x_left%2) = %3 to ceil(x_right%2) &amp;minus; 1 = %4 (a sample exactly on the right edge belongs to the next triangle).</source>
        <translation>Regra top-left: as amostras com x_left &amp;le; x%1 &amp;lt; x_right, pixels ceil(x_left%2) = %3 a ceil(x_right%2) &amp;minus; 1 = %4 (uma amostra exatamente na aresta direita pertence ao triângulo seguinte).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="916"/>
        <source>Inclusive rule: the pixels from ceil(x_left%1) = %2 to floor(x_right%1) = %3, both ends included (a sample exactly on an edge is inside).</source>
        <translation>Regra inclusiva: os pixels de ceil(x_left%1) = %2 a floor(x_right%1) = %3, as duas pontas incluídas (uma amostra exatamente sobre uma aresta está dentro).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="924"/>
        <source>No pixel on this row</source>
        <translation>Nenhum pixel nesta linha</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="925"/>
        <source>the edges cross it between two samples.</source>
        <translation>as arestas a cruzam entre duas amostras.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="926"/>
        <source>they are all off the screen.</source>
        <translation>estão todos fora da tela.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="929"/>
        <source>Span [%1, %2): 1 pixel.</source>
        <translation>Segmento [%1, %2): 1 pixel.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="930"/>
        <source>Span [%1, %2): %3 pixels.</source>
        <translation>Segmento [%1, %2): %3 pixels.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="933"/>
        <source>(cut to the screen&apos;s columns 0 to %1)</source>
        <translation>(cortado às colunas 0 a %1 da tela)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="936"/>
        <source>The pixel at the cursor is x = %1.</source>
        <translation>O pixel no cursor é x = %1.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="984"/>
        <source>At the ends of the span, the barycentrics (&amp;alpha;, &amp;beta;, &amp;gamma;) of the sample with respect to the screen triangle P1 %1, P2 %2, P3 %3 give the depth, from the vertices&apos; z1 = %4, z2 = %5, z3 = %6:</source>
        <translation>Nas pontas do segmento, as coordenadas baricêntricas (&amp;alpha;, &amp;beta;, &amp;gamma;) da amostra em relação ao triângulo de tela P1 %1, P2 %2, P3 %3 dão a profundidade, a partir dos z dos vértices, z1 = %4, z2 = %5, z3 = %6:</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="989"/>
        <source>1/z = 1/z1 + &amp;beta; (1/z2 &amp;minus; 1/z1) + &amp;gamma; (1/z3 &amp;minus; 1/z1) (perspective-correct: 1/z is linear on the screen)</source>
        <translation>1/z = 1/z1 + &amp;beta; (1/z2 &amp;minus; 1/z1) + &amp;gamma; (1/z3 &amp;minus; 1/z1) (com correção de perspectiva: 1/z é linear na tela)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="991"/>
        <source>z = z1 + &amp;beta; (z2 &amp;minus; z1) + &amp;gamma; (z3 &amp;minus; z1)</source>
        <translation>z = z1 + &amp;beta; (z2 &amp;minus; z1) + &amp;gamma; (z3 &amp;minus; z1)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="954"/>
        <source>depth</source>
        <translation>profundidade</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="954"/>
        <source>normal</source>
        <translation>normal</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="957"/>
        <source>not computed (nothing is lit)</source>
        <translation>não calculada (nada é iluminado)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="958"/>
        <source>zero</source>
        <translation>nula</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1007"/>
        <source>Pixel (x, y) is sampled at the point (x, y) itself.</source>
        <translation>O pixel (x, y) é amostrado no próprio ponto (x, y).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1008"/>
        <source>Pixel (x, y) is sampled at (x + %1, y + %1).</source>
        <translation>O pixel (x, y) é amostrado em (x + %1, y + %1).</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1011"/>
        <source>The normal is N1 + &amp;beta; (N2 &amp;minus; N1) + &amp;gamma; (N3 &amp;minus; N1) from the vertex normals, normalised%1.</source>
        <translation>A normal é N1 + &amp;beta; (N2 &amp;minus; N1) + &amp;gamma; (N3 &amp;minus; N1), a partir das normais dos vértices, normalizada%1.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1014"/>
        <source>, with the barycentrics weighted by 1/w (perspective-correct)</source>
        <translation>, com as coordenadas baricêntricas ponderadas por 1/w (correção de perspectiva)</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1038"/>
        <source>Seed 001&apos;s DDA steps the depth and the weights (&amp;beta;, &amp;gamma;) of P2 and P3 as it steps x: down each edge by the edge&apos;s own increment a row, then along the row from their values at x_left by (value at x_right &amp;minus; value at x_left) / (x_right &amp;minus; x_left), one addition a pixel, in double. Every attribute (colour, normal, texture coordinates) is mixed with these weights.</source>
        <translation>O DDA da semente 001 avança a profundidade e os pesos (&amp;beta;, &amp;gamma;) de P2 e P3 como avança x: descendo cada aresta pelo incremento da própria aresta a cada linha, depois ao longo da linha a partir dos seus valores em x_left por (valor em x_right &amp;minus; valor em x_left) / (x_right &amp;minus; x_left), uma soma por pixel, em double. Todo atributo (cor, normal, coordenadas de textura) é misturado com esses pesos.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1044"/>
        <source>On this row %1 = %2 at x_left and %3 at x_right: %1 + %4 a pixel; &amp;beta; + %5 and &amp;gamma; + %6 a pixel.</source>
        <translation>Nesta linha %1 = %2 em x_left e %3 em x_right: %1 + %4 por pixel; &amp;beta; + %5 e &amp;gamma; + %6 por pixel.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1049"/>
        <source>(%1, %2): %3 = %4 + (%1 &amp;minus; %5) &amp;times; %6 = %7.</source>
        <translation>(%1, %2): %3 = %4 + (%1 &amp;minus; %5) &amp;times; %6 = %7.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="1058"/>
        <source>(%1, %2): %3 after %4 additions of %5 = %6.</source>
        <translation>(%1, %2): %3 depois de %4 somas de %5 = %6.</translation>
    </message>
    <message>
        <location filename="../views/scanline_view.cpp" line="732"/>
        <source>Edge walking: from one scanline to the next, each edge&apos;s x changes by its constant dx/dy, one addition per edge and row: x_left(y+1) = x_left(y) + dx/dy. The span between the two crossings is filled; the long edge bounds every row, the upper edge the rows above the middle vertex, the lower edge the rest.</source>
        <translation>Percurso das arestas: de uma linha de varredura à seguinte, o x de cada aresta muda pelo seu dx/dy constante, uma adição por aresta e por linha: x_left(y+1) = x_left(y) + dx/dy. O segmento entre os dois cruzamentos é preenchido; a aresta longa limita todas as linhas, a aresta superior as linhas acima do vértice do meio, a aresta inferior as demais.</translation>
    </message>
</context>
<context>
    <name>rasterlab::StageStrip</name>
    <message>
        <location filename="../views/stage_strip.cpp" line="58"/>
        <source>Camera basis</source>
        <translation>Base da câmera</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="60"/>
        <source>View coordinates</source>
        <translation>Coordenadas de vista</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="62"/>
        <source>Normals</source>
        <translation>Normais</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="64"/>
        <source>Projection</source>
        <translation>Projeção</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="66"/>
        <source>Scan conversion</source>
        <translation>Conversão por varredura</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="68"/>
        <source>Z-buffer</source>
        <translation>Z-buffer</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="70"/>
        <source>Lighting</source>
        <translation>Iluminação</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="78"/>
        <source>Camera</source>
        <translation>Câmera</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="80"/>
        <source>View</source>
        <translation>Vista</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="82"/>
        <source>Scan</source>
        <translation>Varredura</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="92"/>
        <source>no course camera: each draw brings its own view matrix</source>
        <translation>sem câmera do curso: cada desenho traz sua própria matriz de vista</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="96"/>
        <source>nothing is lit: no light reads a normal</source>
        <translation>nada é iluminado: nenhuma luz lê uma normal</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="104"/>
        <source>nothing is lit: each pixel takes its object&apos;s own colour</source>
        <translation>nada é iluminado: cada pixel recebe a cor do seu objeto</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="117"/>
        <source>near clip</source>
        <translation>recorte próximo</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="119"/>
        <source>plain divide</source>
        <translation>divisão simples</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="121"/>
        <source>same side</source>
        <translation>mesmo lado</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="130"/>
        <source>triangles are clipped at the near plane before the divide, so nothing at or behind the eye is divided by its w (the course and GPU-like rules)</source>
        <translation>os triângulos são recortados no plano próximo antes da divisão, então nada no olho ou atrás dele é dividido pelo seu w (as regras do curso e as de GPU)</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="134"/>
        <source>every vertex is divided by its w without clipping, as seed 000 writes it and seed 001&apos;s HW2 does (&quot;we won&apos;t add it&quot;): a triangle behind the eye lands mirrored through the centre, one across the eye plane wraps through infinity</source>
        <translation>cada vértice é dividido pelo seu w sem recorte, como a seed 000 escreve e o HW2 da seed 001 faz (&quot;não vamos adicioná-lo&quot;): um triângulo atrás do olho cai espelhado pelo centro, um que atravessa o plano do olho dá a volta pelo infinito</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="140"/>
        <source>triangles wholly in front of or wholly behind the eye are divided as they are; those across the eye plane are clipped at the near plane</source>
        <translation>os triângulos inteiramente à frente ou inteiramente atrás do olho são divididos como estão; os que atravessam o plano do olho são recortados no plano próximo</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="158"/>
        <source>(skipped)</source>
        <translation>(omitida)</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="166"/>
        <source>%1 is skipped: %2</source>
        <translation>Etapa omitida (%1): %2</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="168"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="173"/>
        <source>Your renderer&apos;s stage passed the check.</source>
        <translation>A etapa do seu renderizador passou na verificação.</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="174"/>
        <source>Your renderer&apos;s stage departs from the lecture&apos;s: see the Check dock.</source>
        <translation>A etapa do seu renderizador se desvia da etapa da aula: veja o painel Verificar.</translation>
    </message>
    <message>
        <location filename="../views/stage_strip.cpp" line="236"/>
        <source>while stepping, stages 5-7 run together, fragment by fragment</source>
        <translation>no passo a passo, as etapas 5-7 rodam juntas, fragmento a fragmento</translation>
    </message>
</context>
<context>
    <name>rasterlab::SteppingBar</name>
    <message>
        <location filename="../views/stepping_bar.cpp" line="75"/>
        <source>Stage</source>
        <translation>Etapa</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="77"/>
        <source>Triangle</source>
        <translation>Triângulo</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="79"/>
        <source>Scanline</source>
        <translation>Linha de varredura</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="81"/>
        <source>Span</source>
        <translation>Segmento</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="83"/>
        <source>Pixel</source>
        <translation>Pixel</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="103"/>
        <source>Jump to &amp;Start</source>
        <translation>Ir ao &amp;início</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="104"/>
        <source>Step &amp;Back</source>
        <translation>&amp;Voltar um passo</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="107"/>
        <source>&amp;Play / Pause</source>
        <translation>&amp;Reproduzir / pausar</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="110"/>
        <source>Step &amp;Forward</source>
        <translation>&amp;Avançar um passo</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="112"/>
        <source>Jump to &amp;End</source>
        <translation>Ir ao &amp;fim</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="114"/>
        <source>&amp;Continue to Breakpoint</source>
        <translation>&amp;Continuar até o ponto de parada</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="140"/>
        <source>Step by</source>
        <translation>Avançar por</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="171"/>
        <source> steps/s</source>
        <translation> passos/s</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="172"/>
        <source>How many steps a second Play makes</source>
        <translation>Quantos passos por segundo a reprodução dá</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="178"/>
        <source>The frame, fragment by fragment: drag to scrub</source>
        <translation>O quadro, fragmento a fragmento: arraste para percorrê-lo</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="262"/>
        <source>stepping is being prepared</source>
        <translation>o passo a passo está sendo preparado</translation>
    </message>
    <message>
        <location filename="../views/stepping_bar.cpp" line="263"/>
        <source>no stepping: %1</source>
        <translation>sem passo a passo: %1</translation>
    </message>
</context>
<context>
    <name>rasterlab::TrapezoidView</name>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="102"/>
        <source>No triangle to show: step into the frame or pick a pixel.</source>
        <translation>Nenhum triângulo para mostrar: avance pelo quadro ou escolha um pixel.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="255"/>
        <source>upper trapezoid</source>
        <translation>trapézio superior</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="256"/>
        <source>lower trapezoid</source>
        <translation>trapézio inferior</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="267"/>
        <source>scanline j</source>
        <translation>linha de varredura j</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="317"/>
        <source>No frame yet.</source>
        <translation>Nenhum quadro ainda.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="319"/>
        <source>Pick a pixel, or step through the frame, to see a triangle split into trapezoids.</source>
        <translation>Escolha um pixel, ou avance pelo quadro, para ver um triângulo dividido em trapézios.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="325"/>
        <source>&lt;b&gt;Triangle %1&lt;/b&gt; of %2</source>
        <translation>&lt;b&gt;Triângulo %1&lt;/b&gt; de %2</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="326"/>
        <source>scanline %1</source>
        <translation>linha de varredura %1</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="327"/>
        <source>pixel %1</source>
        <translation>pixel %1</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="329"/>
        <source>at the stepping cursor</source>
        <translation>no cursor de passo</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="329"/>
        <source>the triangle selected</source>
        <translation>o triângulo selecionado</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="352"/>
        <source>Its area on the screen is zero: it has no inside, no trapezoid, and is not scanned.</source>
        <translation>Sua área na tela é zero: ele não tem interior nem trapézio, e não é varrido.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="360"/>
        <source>Vertices sorted by j: top %1, middle %2, bottom %3. The triangle is split at the middle vertex&apos;s row j = %4.</source>
        <translation>Vértices ordenados por j: topo %1, meio %2, base %3. O triângulo é dividido na linha do vértice do meio, j = %4.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="365"/>
        <source>The long edge from top to bottom meets that row at s = (%1 &amp;minus; %2) / (%3 &amp;minus; %2) = %4: M&apos; = lerp(s, top, bottom) = %5, %6.</source>
        <translation>A aresta longa, do topo à base, encontra essa linha em s = (%1 &amp;minus; %2) / (%3 &amp;minus; %2) = %4: M&apos; = lerp(s, topo, base) = %5, %6.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="371"/>
        <source>Two vertices share a row: the triangle is one trapezoid, two of whose corners are the same vertex.</source>
        <translation>Dois vértices estão na mesma linha: o triângulo é um só trapézio, com dois cantos no mesmo vértice.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="376"/>
        <source>Each corner carries the colour Gouraud shading worked out at its vertex, and the depth.</source>
        <translation>Cada canto leva a cor que o sombreamento de Gouraud calculou no seu vértice, e a profundidade.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="382"/>
        <source>Each corner carries the depth%1 (colours are carried under Gouraud shading, for a triangle with a pixel on the screen, once the frame&apos;s replay is built).</source>
        <translation>Cada canto leva a profundidade%1 (as cores são levadas no sombreamento de Gouraud, para um triângulo com algum pixel na tela, depois que o passo a passo do quadro estiver preparado).</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="384"/>
        <source> as 1/z, which is linear on the screen</source>
        <translation> como 1/z, que é linear na tela</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="389"/>
        <source>corner</source>
        <translation>canto</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="392"/>
        <source>rows</source>
        <translation>linhas</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="400"/>
        <location filename="../views/trapezoid_view.cpp" line="429"/>
        <source>upper</source>
        <translation>superior</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="400"/>
        <location filename="../views/trapezoid_view.cpp" line="429"/>
        <source>lower</source>
        <translation>inferior</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="414"/>
        <source>none</source>
        <translation>nenhuma</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="427"/>
        <source>Scanline j = %1, in the %2 trapezoid</source>
        <translation>Linha de varredura j = %1, no trapézio %2</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="442"/>
        <source>No pixel of this row lies between L and R on the screen.</source>
        <translation>Nenhum pixel desta linha fica entre L e R na tela.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="445"/>
        <source>Pixels i with L_i &amp;le; i%1 &amp;lt; R_i: %2 to %3.</source>
        <translation>Pixels i com L_i &amp;le; i%1 &amp;lt; R_i: %2 a %3.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="450"/>
        <source>Pixels i from ceil(L_i%1) to floor(R_i%1): %2 to %3.</source>
        <translation>Pixels i de ceil(L_i%1) a floor(R_i%1): %2 a %3.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="461"/>
        <source>Pixel i = %1</source>
        <translation>Pixel i = %1</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="471"/>
        <source>The depth test&apos;s z there: %1 (stepped by seed 001&apos;s DDA in double, then rounded to float).</source>
        <translation>O z do teste de profundidade ali: %1 (avançado pelo DDA da semente 001 em double, depois arredondado para float).</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="475"/>
        <source>z = 1 / (1/z) = %1; the depth test&apos;s z there: %2 (from the barycentrics, in float).</source>
        <translation>z = 1 / (1/z) = %1; o z do teste de profundidade ali: %2 (a partir das coordenadas baricêntricas, em float).</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="478"/>
        <source>The depth test&apos;s z there: %1 (from the barycentrics, in float).</source>
        <translation>O z do teste de profundidade ali: %1 (a partir das coordenadas baricêntricas, em float).</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="486"/>
        <source>The row through the middle vertex belongs to the lower trapezoid only, so no row is scanned twice.</source>
        <translation>A linha que passa pelo vértice do meio pertence só ao trapézio inferior, então nenhuma linha é varrida duas vezes.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="490"/>
        <source>Pixel (i, j) is sampled at (i + %1, j + %1): t_j and t_i use those.</source>
        <translation>O pixel (i, j) é amostrado em (i + %1, j + %1): t_j e t_i usam esses valores.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="492"/>
        <source>Top-left rule: a sample exactly on the bottom vertex&apos;s row or on R belongs to the next triangle.</source>
        <translation>Regra top-left: uma amostra exatamente na linha do vértice da base ou sobre R pertence ao triângulo seguinte.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="494"/>
        <source>Inclusive rule: samples exactly on L, R or the bottom row are inside.</source>
        <translation>Regra inclusiva: as amostras exatamente sobre L, sobre R ou na linha da base estão dentro.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="497"/>
        <source>These rules interpolate colours perspective-correctly (weights over w): the lerps of the seed, linear on the screen, are what the course rules do; the rows and pixels are the same either way.</source>
        <translation>Estas regras interpolam as cores com correção de perspectiva (pesos divididos por w): os lerps da semente, lineares na tela, são o que fazem as regras do curso; as linhas e os pixels são os mesmos de todo modo.</translation>
    </message>
    <message>
        <location filename="../views/trapezoid_view.cpp" line="502"/>
        <source>The same rows and pixels as the edge walk (scan conversion view): L_i and R_i are where the scanline crosses the triangle&apos;s edges.</source>
        <translation>As mesmas linhas e pixels do percurso das arestas (painel de conversão por varredura): L_i e R_i são onde a linha de varredura cruza as arestas do triângulo.</translation>
    </message>
</context>
<context>
    <name>rasterlab::VertexTableModel</name>
    <message>
        <location filename="../views/vertex_table.cpp" line="143"/>
        <source>%1 made by clipping (edge %2-%3, t = %4)</source>
        <translation>%1 criado pelo recorte (aresta %2-%3, t = %4)</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="150"/>
        <source>pView = pView(%1) + t (pView(%2) - pView(%1)), on the plane that cut the edge</source>
        <translation>pView = pView(%1) + t (pView(%2) - pView(%1)), no plano que cortou a aresta</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="163"/>
        <source>At or behind the near plane: not projected; the triangles through it are clipped</source>
        <translation>No plano próximo ou atrás dele: não é projetado; os triângulos que passam por ele são recortados</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="166"/>
        <location filename="../views/vertex_table.cpp" line="170"/>
        <source>behind</source>
        <translation>atrás</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="172"/>
        <source>Exact: %1</source>
        <translation>Exato: %1</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="183"/>
        <source>Mixed along the edge it was made on, as shading does (normalised per pixel)</source>
        <translation>Misturada ao longo da aresta em que o vértice foi criado, como faz o sombreamento (normalizada por pixel)</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="206"/>
        <source>Draw</source>
        <translation>Desenho</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="208"/>
        <source>Vertex</source>
        <translation>Vértice</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="210"/>
        <source>World (x, y, z)</source>
        <translation>Mundo (x, y, z)</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="212"/>
        <source>View pView</source>
        <translation>Vista pView</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="214"/>
        <source>NDC pNdc</source>
        <translation>NDC pNdc</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="216"/>
        <source>Screen pScreen</source>
        <translation>Tela pScreen</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="218"/>
        <source>Normal nView</source>
        <translation>Normal nView</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="226"/>
        <source>The draw (object) the vertex belongs to</source>
        <translation>O desenho (objeto) ao qual o vértice pertence</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="228"/>
        <source>The vertex number as in the file (1-based); vertices made by clipping come after the draw&apos;s own</source>
        <translation>O número do vértice como no arquivo (a partir de 1); os vértices criados pelo recorte vêm depois dos do próprio desenho</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="232"/>
        <source>P = worldFromModel · P_model</source>
        <translation>P = worldFromModel · P_model</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="234"/>
        <source>pView = [U; V; N](P − C) for the course camera, or the draw&apos;s view matrix times P_model</source>
        <translation>pView = [U; V; N](P − C) para a câmera do curso, ou a matriz de vista do desenho vezes P_model</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="238"/>
        <source>pNdc = ((d/hx) x/z, (d/hy) y/z) for the course camera, or pClip.xy / pClip.w with pClip = clipFromView · pView</source>
        <translation>pNdc = ((d/hx) x/z, (d/hy) y/z) para a câmera do curso, ou pClip.xy / pClip.w com pClip = clipFromView · pView</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="242"/>
        <source>pScreen = ((x_ndc + 1) w/2, (1 − y_ndc) h/2), truncated (snapped to the rules&apos; grid); the tooltip holds the exact value</source>
        <translation>pScreen = ((x_ndc + 1) w/2, (1 − y_ndc) h/2), truncado (ajustado à grade das regras); a dica mostra o valor exato</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="246"/>
        <source>The view-space vertex normal: the normalised sum of the normals of the triangles around it (stage 3)</source>
        <translation>A normal do vértice no espaço de vista: a soma normalizada das normais dos triângulos ao seu redor (etapa 3)</translation>
    </message>
</context>
<context>
    <name>rasterlab::VertexTableView</name>
    <message>
        <location filename="../views/vertex_table.cpp" line="281"/>
        <source>Only the selected triangle&apos;s vertices</source>
        <translation>Só os vértices do triângulo selecionado</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="348"/>
        <source>%1 vertices, %2 of them made by clipping</source>
        <translation>%1 vértices, %2 deles criados pelo recorte</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="349"/>
        <source>%1 vertices</source>
        <translation>%1 vértices</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="478"/>
        <source>&lt;p&gt;Select a row, or pick a pixel in the image: its triangle&apos;s three vertices are selected. The numbers of the selected vertex are worked through each formula here.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Selecione uma linha, ou escolha um pixel na imagem: os três vértices do seu triângulo são selecionados. Os números do vértice selecionado são calculados aqui, fórmula por fórmula.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="481"/>
        <source>&lt;p&gt;No frame yet.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Nenhum quadro ainda.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="505"/>
        <source>Vertex %1 of draw %2 (%3)</source>
        <translation>Vértice %1 do desenho %2 (%3)</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="506"/>
        <source>Vertex %1 of %2</source>
        <translation>Vértice %1 de %2</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="513"/>
        <source>&lt;p&gt;Made by clipping the edge %1-%2 where it crosses a plane (the near plane or a clip plane), at t = %3:&lt;br&gt;pView = pView&lt;sub&gt;%1&lt;/sub&gt; + t (pView&lt;sub&gt;%2&lt;/sub&gt; − pView&lt;sub&gt;%1&lt;/sub&gt;) = %4 + %3 (%5 − %4) = &lt;b&gt;%6&lt;/b&gt;&lt;br&gt;World: P = %7 (the same interpolation).&lt;/p&gt;</source>
        <translation>&lt;p&gt;Criado ao recortar a aresta %1-%2 onde ela cruza um plano (o plano próximo ou um plano de recorte), em t = %3:&lt;br&gt;pView = pView&lt;sub&gt;%1&lt;/sub&gt; + t (pView&lt;sub&gt;%2&lt;/sub&gt; − pView&lt;sub&gt;%1&lt;/sub&gt;) = %4 + %3 (%5 − %4) = &lt;b&gt;%6&lt;/b&gt;&lt;br&gt;Mundo: P = %7 (a mesma interpolação).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="524"/>
        <source>&lt;p&gt;World: P = M(t) · worldFromModel · %1 = &lt;b&gt;%2&lt;/b&gt; (M: the animation matrix at t = %3 s)&lt;/p&gt;</source>
        <translation>&lt;p&gt;Mundo: P = M(t) · worldFromModel · %1 = &lt;b&gt;%2&lt;/b&gt; (M: a matriz de animação em t = %3 s)&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="529"/>
        <source>&lt;p&gt;World: P = P&lt;sub&gt;model&lt;/sub&gt; = &lt;b&gt;%1&lt;/b&gt; (worldFromModel is the identity)&lt;/p&gt;</source>
        <translation>&lt;p&gt;Mundo: P = P&lt;sub&gt;model&lt;/sub&gt; = &lt;b&gt;%1&lt;/b&gt; (worldFromModel é a identidade)&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="533"/>
        <source>&lt;p&gt;World: P = worldFromModel · %1 = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Mundo: P = worldFromModel · %1 = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="539"/>
        <source>&lt;p&gt;View: pView = [U; V; N](P − C), with C = %1:&lt;br&gt;P − C = %2&lt;br&gt;x = U · (P − C) = %3 · %2 = %4&lt;br&gt;y = V · (P − C) = %5 · %2 = %6&lt;br&gt;z = N · (P − C) = %7 · %2 = %8&lt;br&gt;pView = &lt;b&gt;%9&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Vista: pView = [U; V; N](P − C), com C = %1:&lt;br&gt;P − C = %2&lt;br&gt;x = U · (P − C) = %3 · %2 = %4&lt;br&gt;y = V · (P − C) = %5 · %2 = %6&lt;br&gt;z = N · (P − C) = %7 · %2 = %8&lt;br&gt;pView = &lt;b&gt;%9&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="547"/>
        <source>&lt;p&gt;View: pView = viewFromModel · P&lt;sub&gt;model&lt;/sub&gt; (the draw&apos;s own view matrix) = &lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Vista: pView = viewFromModel · P&lt;sub&gt;model&lt;/sub&gt; (a matriz de vista do próprio desenho) = &lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="555"/>
        <source>&lt;p&gt;z = %1 is not beyond the near plane (w = %2): the vertex is behind, not projected; the triangles through it are clipped there.&lt;/p&gt;</source>
        <translation>&lt;p&gt;z = %1 não está além do plano próximo (w = %2): o vértice está atrás e não é projetado; os triângulos que passam por ele são recortados ali.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="563"/>
        <source>&lt;p&gt;NDC: pNdc = ((d/hx) x/z, (d/hy) y/z) = ((%1/%2) · %3/%4, (%1/%5) · %6/%4) = &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;NDC: pNdc = ((d/hx) x/z, (d/hy) y/z) = ((%1/%2) · %3/%4, (%1/%5) · %6/%4) = &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="568"/>
        <source>&lt;p&gt;Clip: pClip = clipFromView · pView = %1&lt;br&gt;NDC: pNdc = pClip.xy / pClip.w = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Recorte: pClip = clipFromView · pView = %1&lt;br&gt;NDC: pNdc = pClip.xy / pClip.w = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="577"/>
        <source>not snapped</source>
        <translation>sem arredondamento para a grade</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="579"/>
        <source>truncated, as C&apos;s (int) does</source>
        <translation>truncado, como faz o (int) do C</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="581"/>
        <source>truncated to a grid of 1/%1 pixel</source>
        <translation>truncado para uma grade de 1/%1 de pixel</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="583"/>
        <source>rounded to the nearest 1/%1 pixel</source>
        <translation>arredondado para o 1/%1 de pixel mais próximo</translation>
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
        <translation>&lt;p&gt;Tela: pScreen = (x&lt;sub&gt;ndc&lt;/sub&gt; w/2 + w/2, y&lt;sub&gt;ndc&lt;/sub&gt; h/2 + h/2) = (%1 · %2 + %2, %3 · %4 + %4) = %5, %6: &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="597"/>
        <source>&lt;p&gt;Screen: pScreen = ((x&lt;sub&gt;ndc&lt;/sub&gt; + 1) w/2, %1) = ((%2 + 1) · %3, %4) = %5, %6: &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Tela: pScreen = ((x&lt;sub&gt;ndc&lt;/sub&gt; + 1) w/2, %1) = ((%2 + 1) · %3, %4) = %5, %6: &lt;b&gt;%7&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="606"/>
        <source>&lt;p&gt;Normal: mixed along the edge like pView, %1; shading normalises it per pixel.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normal: misturada ao longo da aresta como pView, %1; o sombreamento a normaliza por pixel.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="610"/>
        <source>&lt;p&gt;Normal: the file&apos;s normal carried to view space by the inverse transpose of viewFromModel: nView = &lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normal: a normal do arquivo levada ao espaço de vista pela inversa transposta de viewFromModel: nView = &lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="617"/>
        <source>&lt;p&gt;Normal: the normalised sum of the normals of the %1 triangles around it: nView = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normal: a soma normalizada das normais dos %1 triângulos ao seu redor: nView = &lt;b&gt;%2&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../views/vertex_table.cpp" line="623"/>
        <source>&lt;p&gt;Normal: none, %1.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Normal: nenhuma, %1.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>rasterlab::ZBufferView</name>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="165"/>
        <source>Automatic range (nearest to farthest drawn)</source>
        <translation>Faixa automática (do mais próximo ao mais distante desenhado)</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="182"/>
        <source>Grey</source>
        <translation>Cinza</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="183"/>
        <source>False colour</source>
        <translation>Cores falsas</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="195"/>
        <source>Nearest (white / red):</source>
        <translation>Mais próximo (branco / vermelho):</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="196"/>
        <source>Farthest (dark / blue):</source>
        <translation>Mais distante (escuro / azul):</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="197"/>
        <source>Colours:</source>
        <translation>Cores:</translation>
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
        <translation>guardado</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="332"/>
        <source>the view-space z of P&apos;</source>
        <translation>o z de P&apos; no espaço de vista</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="332"/>
        <source>the NDC z</source>
        <translation>o z em NDC</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="340"/>
        <source>&lt;b&gt;Z-buffer.&lt;/b&gt; Every pixel starts at %1. Each fragment&apos;s depth %2 (%3) is compared with the stored one; it is written, with its colour, only when %4. So far: %5 fragments tested, %6 written, %7 rejected.</source>
        <translation>&lt;b&gt;Z-buffer.&lt;/b&gt; Todo pixel começa em %1. A profundidade de cada fragmento, %2 (%3), é comparada com a armazenada; ela é escrita, com sua cor, só quando %4. Até agora: %5 fragmentos testados, %6 escritos, %7 rejeitados.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="390"/>
        <source>%1 tested · %2 written · %3 rejected</source>
        <translation>%1 testados · %2 escritos · %3 rejeitados</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="399"/>
        <source>No frame yet.</source>
        <translation>Nenhum quadro ainda.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="416"/>
        <source>No pixel holds a triangle: the buffer is all clear value.</source>
        <translation>Nenhum pixel contém um triângulo: o buffer inteiro está no valor de limpeza.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="423"/>
        <source>Drawn depths from %1 to %2; shown from %3 to %4.</source>
        <translation>Profundidades desenhadas de %1 a %2; exibidas de %3 a %4.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="429"/>
        <source>%1 pixels nearer and %2 farther than the range are drawn at its ends.</source>
        <translation>%1 pixels mais próximos e %2 mais distantes que a faixa aparecem nas suas extremidades.</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="443"/>
        <source>+inf</source>
        <translation>+inf</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="444"/>
        <source>x %1, y %2: no triangle; the depth stays at the clear value %3</source>
        <translation>x %1, y %2: nenhum triângulo; a profundidade fica no valor de limpeza %3</translation>
    </message>
    <message>
        <location filename="../views/zbuffer_view.cpp" line="449"/>
        <source>x %1, y %2: depth %3, triangle %4</source>
        <translation>x %1, y %2: profundidade %3, triângulo %4</translation>
    </message>
</context>
</TS>
