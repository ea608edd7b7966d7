#include "scene_document.h"

#include <QFile>
#include <QSaveFile>

#include <new>

#include "app/documents/command_file.h"
#include "app/documents/default_scene_resource.h"
#include "app/documents/input_file.h"
#include "pipeline/io/course_writers.h"
#include "pipeline/render/animation.h"
#include "pipeline/stages/camera_basis.h"

namespace rasterlab {

using rl::operator""_msg;  // message templates, translated in the window (pipeline_messages.h)

rl::Status SceneDocument::loadDefault() {
    SceneDocument fresh;
    fresh.m_settings = m_settings;
    fresh.m_cameraLayout = m_cameraLayout;
    fresh.m_lightingLayout = m_lightingLayout;
    fresh.m_partsReplaced = m_partsReplaced;
    for (CoursePart part : kCourseParts) {
        auto status = fresh.open(part, defaultScenePath(part));
        if (!status) return status;
    }
    fresh.m_loaded = true;
    *this = std::move(fresh);
    return rl::success();
}

namespace {

std::string_view viewOf(const QByteArray& bytes) {
    return {bytes.constData(), std::size_t(bytes.size())};
}

// Whether a file's first bytes look like a command file.
bool isCommandFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return false;
    return rl::looksLikeHw2(viewOf(file.read(4096)));
}

}  // namespace

namespace {

// A load that may meet a file larger than the memory: std::bad_alloc becomes an error,
// and the document is unchanged.
template <typename Load>
auto guarded(const QString& path, Load load) -> decltype(load()) {
    try {
        return load();
    } catch (const std::bad_alloc&) {
        return rl::makeError(rl::ErrorCode::Range, rl::SourceLocation{path.toStdString(), 0, 0},
                             "not enough memory to read this file"_msg);
    }
}

}  // namespace

rl::Status SceneDocument::openCommandFile(const QString& path) {
    rl::Diagnostics diagnostics;
    auto file = guarded(path, [&] { return loadCommandFile(path, diagnostics); });
    if (!file) return file.error();
    m_commandFile = std::move(file).value();
    m_commandFileProjection = m_commandFile->images.front().scene.nearPlane.mode;
    m_commandFilePath = path;
    m_commandFileDiagnostics = std::move(diagnostics);
    m_imageIndex = 0;
    m_loaded = true;
    return rl::success();
}

QStringList SceneDocument::imageNames() const {
    QStringList names;
    if (m_commandFile)
        for (const auto& image : m_commandFile->images)
            names << QString::fromStdString(image.fileName);
    return names;
}

void SceneDocument::setImageIndex(int index) {
    if (m_commandFile && index >= 0 && index < int(m_commandFile->images.size()))
        m_imageIndex = index;
}

namespace {

// Why a camera has no basis (N or V zero or parallel, d, hx or hy zero), if it has none: it
// would fail every render, and a file of it would not load.
std::optional<rl::Error> basisError(const rl::CourseCamera& camera) {
    rl::Scene check;
    check.camera = camera;
    rl::Diagnostics warnings;  // the render reports them
    auto basis = rl::CameraBasisStage().run(check, warnings);
    if (!basis) return basis.error();
    return std::nullopt;
}

bool isResource(const QString& path) {
    return path.startsWith(QStringLiteral(":/"));
}

// The layout a camera or lighting file that was just read is in: the one chosen, or the one
// detection finds in it (always detection for the files embedded in the program).
template <typename Layout, typename Detect>
Layout layoutOfFile(const QString& path, Layout chosen, Detect detect) {
    if (chosen != Layout::Auto && !isResource(path)) return chosen;
    auto bytes = readInputFile(path);
    if (!bytes) return Layout::Ufpe;  // read a moment ago; not reached unless it vanished
    return detect(viewOf(bytes.value())).value_or(Layout::Ufpe);
}

}  // namespace

rl::Status SceneDocument::open(Part part, const QString& path) {
    if (part == Part::Object && isCommandFile(path)) return openCommandFile(path);
    rl::Diagnostics diagnostics;
    switch (part) {
        case Part::Camera: {
            auto camera = loadCamera(path, diagnostics, m_cameraLayout);
            if (!camera) return camera.error();
            // A camera without a basis is refused, so that the previous one stays.
            if (auto error = basisError(camera.value())) return *error;
            m_parts.camera = camera.value();
            m_fileCamera = camera.value();
            m_cameraFileLayout = layoutOfFile(path, m_cameraLayout, rl::detectCameraLayout);
            m_lastSaved[index(part)].clear();
            ++m_partsReplaced;
            break;
        }
        case Part::Lighting: {
            auto lighting = loadLighting(path, diagnostics, m_lightingLayout);
            if (!lighting) return lighting.error();
            m_parts.lighting = lighting.value();
            m_fileLighting = lighting.value();
            m_lightingFileLayout = layoutOfFile(path, m_lightingLayout, rl::detectLightingLayout);
            m_lastSaved[index(part)].clear();
            ++m_partsReplaced;
            break;
        }
        case Part::Object: {
            auto object = guarded(path, [&] { return loadObject(path, diagnostics); });
            if (!object) return object.error();
            m_parts.object = object.value();
            break;
        }
    }
    m_sources[index(part)] = path;
    m_partDiagnostics[index(part)] = std::move(diagnostics);
    m_commandFile.reset();  // the course scene is shown again
    m_commandFilePath.clear();
    return rl::success();
}

rl::Status SceneDocument::setCameraLayout(rl::CameraLayout layout) {
    m_cameraLayout = layout;
    const QString path = source(Part::Camera);
    if (m_commandFile || path.isEmpty() || isResource(path)) return rl::success();
    return open(Part::Camera, path);
}

rl::Status SceneDocument::setLightingLayout(rl::LightingLayout layout) {
    m_lightingLayout = layout;
    const QString path = source(Part::Lighting);
    if (m_commandFile || path.isEmpty() || isResource(path)) return rl::success();
    return open(Part::Lighting, path);
}

rl::Diagnostics SceneDocument::diagnostics() const {
    if (m_commandFile) return m_commandFileDiagnostics;
    rl::Diagnostics all;
    for (const auto& d : m_partDiagnostics) all.append(d);
    return all;
}

void SceneDocument::setSize(int width, int height) {
    m_settings.width = width;
    m_settings.height = height;
}

rl::NearPlane::Mode SceneDocument::projection() const {
    return m_commandFile ? m_commandFileProjection : m_settings.nearPlane.mode;
}

void SceneDocument::setProjection(rl::NearPlane::Mode mode) {
    if (m_commandFile)
        m_commandFileProjection = mode;
    else
        m_settings.nearPlane.mode = mode;
}

std::shared_ptr<const rl::Scene> SceneDocument::scene() const {
    auto scene = std::make_shared<rl::Scene>(
        m_commandFile ? m_commandFile->images[std::size_t(m_imageIndex)].scene
                      : rl::makeCourseScene(m_parts, m_settings));
    scene->nearPlane.mode = projection();
    if (m_animation.enabled) rl::animateEveryDraw(*scene, m_animation.motion, m_animation.time);
    return scene;
}

// ---- Editing without files

int SceneDocument::componentCount(Field field) {
    switch (field) {
        case Field::C:
        case Field::N:
        case Field::V:
        case Field::LightPosition:
        case Field::LightIntensity:
        case Field::LightAttenuation:
        case Field::LightSpotDirection:
        case Field::Ambient:
        case Field::Kd:
        case Field::Od:
        case Field::Emission:
            return 3;
        default:
            return 1;
    }
}

bool SceneDocument::isLightField(Field field) {
    switch (field) {
        case Field::LightPosition:
        case Field::LightIntensity:
        case Field::LightDirectional:
        case Field::LightAttenuation:
        case Field::LightSpotDirection:
        case Field::LightSpotCutoff:
        case Field::LightSpotExponent:
            return true;
        default:
            return false;
    }
}

bool SceneDocument::insertLight(std::size_t index, const rl::Light& light) {
    std::vector<rl::Light>& lights = m_parts.lighting.lights;
    if (index > lights.size()) return false;
    lights.insert(lights.begin() + std::ptrdiff_t(index), light);
    return true;
}

std::optional<rl::Light> SceneDocument::takeLight(std::size_t index) {
    std::vector<rl::Light>& lights = m_parts.lighting.lights;
    if (index >= lights.size() || lights.size() < 2) return std::nullopt;
    const rl::Light light = lights[index];
    lights.erase(lights.begin() + std::ptrdiff_t(index));
    return light;
}

std::optional<SceneDocument::Part> SceneDocument::partOf(Field field) {
    switch (field) {
        case Field::C:
        case Field::N:
        case Field::V:
        case Field::D:
        case Field::Hx:
        case Field::Hy:
            return Part::Camera;
        case Field::Shading:
            return std::nullopt;
        default:
            return Part::Lighting;
    }
}

namespace {

template <typename Vec>
SceneDocument::Numbers numbersOf(const Vec& v) {
    return {double(v[0]), double(v[1]), double(v[2])};
}

SceneDocument::Numbers scalarNumbers(double v) {
    return {v, 0.0, 0.0};
}

rl::dvec3 dvec3Of(const SceneDocument::Numbers& n) {
    return {n[0], n[1], n[2]};
}

rl::vec3 vec3Of(const SceneDocument::Numbers& n) {
    return {float(n[0]), float(n[1]), float(n[2])};
}

}  // namespace

SceneDocument::Numbers SceneDocument::value(Field field, std::size_t light) const {
    const rl::CourseCamera& c = m_parts.camera;
    const rl::CourseLighting& l = m_parts.lighting;
    const rl::Material& m = l.material;
    const rl::Light* lit = light < l.lights.size() ? &l.lights[light] : nullptr;  // or none
    switch (field) {
        case Field::C:
            return numbersOf(c.c);
        case Field::N:
            return numbersOf(c.n);
        case Field::V:
            return numbersOf(c.v);
        case Field::D:
            return scalarNumbers(c.d);
        case Field::Hx:
            return scalarNumbers(c.hx);
        case Field::Hy:
            return scalarNumbers(c.hy);
        case Field::LightPosition:
            return lit ? numbersOf(lit->pWorld) : Numbers{};
        case Field::LightIntensity:
            return lit ? numbersOf(lit->intensity) : Numbers{};
        case Field::LightDirectional:
            return lit ? scalarNumbers(lit->pWorld.w == 0.0 ? 1 : 0) : Numbers{};
        case Field::LightAttenuation:
            return lit ? numbersOf(lit->attenuation) : Numbers{};
        case Field::LightSpotDirection:
            return lit ? numbersOf(lit->spotDirection) : Numbers{};
        case Field::LightSpotCutoff:
            return lit ? scalarNumbers(lit->spotCutoff) : Numbers{};
        case Field::LightSpotExponent:
            return lit ? scalarNumbers(lit->spotExponent) : Numbers{};
        case Field::Emission:
            return numbersOf(m.emission);
        case Field::TwoSided:
            return scalarNumbers(l.twoSided ? 1.0 : 0.0);
        case Field::BlinnPhong:
            return scalarNumbers(l.specular == rl::SpecularModel::BlinnPhong ? 1.0 : 0.0);
        case Field::Ambient:
            return numbersOf(l.ambientIntensity);
        case Field::Ka:
            return scalarNumbers(m.ka);
        case Field::Kd:
            return numbersOf(m.kd);
        case Field::Od:
            return numbersOf(m.od);
        case Field::Ks:
            return scalarNumbers(m.ks);
        case Field::Shininess:
            return scalarNumbers(m.shininess);
        case Field::Shading:
            return scalarNumbers(double(m_settings.shading));
    }
    return {};
}

void SceneDocument::setValue(Field field, const Numbers& value, std::size_t light) {
    rl::CourseCamera& c = m_parts.camera;
    rl::CourseLighting& l = m_parts.lighting;
    rl::Material& m = l.material;
    rl::Light* lit = light < l.lights.size() ? &l.lights[light] : nullptr;  // or none
    switch (field) {
        case Field::C:
            c.c = dvec3Of(value);
            break;
        case Field::N:
            c.n = dvec3Of(value);
            break;
        case Field::V:
            c.v = dvec3Of(value);
            break;
        case Field::D:
            c.d = value[0];
            break;
        case Field::Hx:
            c.hx = value[0];
            break;
        case Field::Hy:
            c.hy = value[0];
            break;
        case Field::LightPosition:
            // w stays: a directional light's Pl is its direction.
            if (lit) lit->pWorld = rl::dvec4(dvec3Of(value), lit->pWorld.w);
            break;
        case Field::LightIntensity:
            if (lit) lit->intensity = vec3Of(value);
            break;
        case Field::LightDirectional:
            if (lit) lit->pWorld.w = value[0] != 0.0 ? 0.0 : 1.0;
            break;
        case Field::LightAttenuation:
            if (lit) lit->attenuation = vec3Of(value);
            break;
        case Field::LightSpotDirection:
            if (lit) lit->spotDirection = dvec3Of(value);
            break;
        case Field::LightSpotCutoff:
            if (lit) lit->spotCutoff = float(value[0]);
            break;
        case Field::LightSpotExponent:
            if (lit) lit->spotExponent = float(value[0]);
            break;
        case Field::Emission:
            m.emission = vec3Of(value);
            break;
        case Field::TwoSided:
            l.twoSided = value[0] != 0.0;
            break;
        case Field::BlinnPhong:
            l.specular = value[0] != 0.0 ? rl::SpecularModel::BlinnPhong : rl::SpecularModel::Phong;
            break;
        case Field::Ambient:
            l.ambientIntensity = vec3Of(value);
            break;
        case Field::Ka:
            m.ka = float(value[0]);
            break;
        case Field::Kd:
            m.kd = vec3Of(value);
            break;
        case Field::Od:
            m.od = vec3Of(value);
            break;
        case Field::Ks:
            m.ks = float(value[0]);
            break;
        case Field::Shininess:
            m.shininess = float(value[0]);
            break;
        case Field::Shading:
            setShading(static_cast<rl::ShadingModel>(int(value[0])));
            break;
    }
}

namespace {

bool sameValues(const rl::CourseCamera& a, const rl::CourseCamera& b) {
    return a.c == b.c && a.n == b.n && a.v == b.v && a.d == b.d && a.hx == b.hx && a.hy == b.hy;
}

bool sameValues(const rl::CourseLighting& a, const rl::CourseLighting& b) {
    const rl::Material &x = a.material, &y = b.material;
    if (!(x.ka == y.ka && x.kd == y.kd && x.od == y.od && x.ks == y.ks &&
          x.shininess == y.shininess && x.emission == y.emission &&
          a.ambientIntensity == b.ambientIntensity && a.twoSided == b.twoSided &&
          a.specular == b.specular && a.lights.size() == b.lights.size()))
        return false;
    for (std::size_t k = 0; k < a.lights.size(); ++k) {
        const rl::Light &p = a.lights[k], &q = b.lights[k];
        if (p.pWorld != q.pWorld || p.intensity != q.intensity || p.attenuation != q.attenuation ||
            p.spotDirection != q.spotDirection || p.spotCutoff != q.spotCutoff ||
            p.spotExponent != q.spotExponent)
            return false;
    }
    return true;
}

rl::Error saveError(const QString& path, rl::ErrorCode code, rl::Message message) {
    return rl::makeError(code, rl::SourceLocation{path.toStdString(), 0, 0}, std::move(message));
}

}  // namespace

bool SceneDocument::isModified(Part part) const {
    switch (part) {
        case Part::Camera:
            return !sameValues(m_parts.camera, m_fileCamera);
        case Part::Lighting:
            return !sameValues(m_parts.lighting, m_fileLighting);
        case Part::Object:
            break;
    }
    return false;
}

bool SceneDocument::isModified() const {
    return isModified(Part::Camera) || isModified(Part::Lighting);
}

bool SceneDocument::needsPath(Part part) const {
    const QString path = source(part);
    return path.isEmpty() || isResource(path);
}

rl::Status SceneDocument::save(Part part) {
    if (needsPath(part))
        return saveError(source(part), rl::ErrorCode::Usage,
                         "the built-in scene's files cannot be written: save it to a file of "
                         "your own (Save As)"_msg);
    return writePart(part, source(part), m_cameraFileLayout, m_lightingFileLayout);
}

rl::Status SceneDocument::saveAs(Part part, const QString& path) {
    return writePart(part, path, m_cameraFileLayout, m_lightingFileLayout);
}

rl::Status SceneDocument::saveCameraAs(const QString& path, rl::CameraLayout layout) {
    return writePart(Part::Camera, path, layout, m_lightingFileLayout);
}

rl::Status SceneDocument::saveLightingAs(const QString& path, rl::LightingLayout layout) {
    return writePart(Part::Lighting, path, m_cameraFileLayout, layout);
}

bool SceneDocument::fileHoldsLastSave(Part part) const {
    if (part == Part::Object || m_lastSaved[index(part)].isEmpty()) return false;
    QFile file(source(part));
    if (!file.open(QIODevice::ReadOnly)) return false;
    return file.readAll() == m_lastSaved[index(part)];
}

rl::Status SceneDocument::writePart(Part part, const QString& path, rl::CameraLayout cameraLayout,
                                    rl::LightingLayout lightingLayout) {
    if (part == Part::Object)
        return saveError(path, rl::ErrorCode::Usage, "the object is not edited, so not saved"_msg);
    if (path.isEmpty() || isResource(path))
        return saveError(path, rl::ErrorCode::Usage,
                         "cannot write into the built-in resources"_msg);
    const std::string fileName = path.toStdString();
    const bool camera = part == Part::Camera;
    if (camera) {
        if (auto error = basisError(m_parts.camera))
            return saveError(path, rl::ErrorCode::Degenerate,
                             "the camera was not saved, as it would not load again: %1"_msg(
                                 error->translatable));
    }

    // The file's present text gives its line ending and, in a key = value file, the lines of
    // the other part; a file in a line layout is replaced whole.
    QByteArray previous;
    if (QFile::exists(path)) {
        if (auto bytes = readInputFile(path)) previous = bytes.value();
    }
    const bool previousIsKeyValue =
        camera ? rl::detectCameraLayout(viewOf(previous)) == rl::CameraLayout::KeyValue
               : rl::detectLightingLayout(viewOf(previous)) == rl::LightingLayout::KeyValue;
    const bool keyValue = camera ? cameraLayout == rl::CameraLayout::KeyValue
                                 : lightingLayout == rl::LightingLayout::KeyValue;
    if (keyValue && !previousIsKeyValue) {
        // Only the line ending of a file in another layout carries over.
        previous = previous.contains("\r\n") ? QByteArray("\r\n") : QByteArray();
    }
    auto text = camera ? rl::writeCameraFile(m_parts.camera, cameraLayout, viewOf(previous))
                       : rl::writeLightingFile(m_parts.lighting, lightingLayout, viewOf(previous));
    if (!text) return saveError(path, text.error().code, text.error().translatable);

    // Read back before writing: the file must give these values again.
    rl::Diagnostics diagnostics;
    std::optional<rl::CourseCamera> cameraBack;
    std::optional<rl::CourseLighting> lightingBack;
    bool same = false;
    if (camera) {
        auto back = rl::readCameraFile(*text, fileName, diagnostics, cameraLayout);
        if (back) cameraBack = back.value();
        same = back && sameValues(*back, m_parts.camera);
    } else {
        auto back = rl::readLightingFile(*text, fileName, diagnostics, lightingLayout);
        if (back) lightingBack = back.value();
        same = back && sameValues(*back, m_parts.lighting);
    }
    if (!same)
        return saveError(path, rl::ErrorCode::Unsupported,
                         "not saved: the text written does not read back as the same values"_msg);

    const QByteArray bytes = QByteArray::fromStdString(*text);
    // Unbuffered, so that a short write is seen here: with a buffer, Qt 6.4's QSaveFile
    // reports a write cut short by a full disk or a file size limit as a successful commit,
    // replacing the file with a truncated one.
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return saveError(path, rl::ErrorCode::Io,
                         "cannot write the file: %1"_msg(file.errorString().toStdString()));
    const qint64 written = file.write(bytes);
    if (written != bytes.size()) {
        file.cancelWriting();
        const rl::Message why =
            written < 0 ? rl::Message::untranslated(file.errorString().toStdString())
                        : "only %1 of %2 bytes could be written (is the disk full?)"_msg(
                              written, bytes.size());
        return saveError(path, rl::ErrorCode::Io,
                         "cannot write the file (it is left as it was): %1"_msg(why));
    }
    if (!file.commit())
        return saveError(path, rl::ErrorCode::Io,
                         "cannot write the file (it is left as it was): %1"_msg(
                             file.errorString().toStdString()));

    // The part now comes from this file: its locations, warnings, layout and saved values.
    if (camera) {
        m_parts.camera.where = cameraBack->where;
        m_fileCamera = m_parts.camera;
        m_cameraFileLayout = cameraLayout;
    } else {
        for (std::size_t k = 0; k < m_parts.lighting.lights.size(); ++k)
            m_parts.lighting.lights[k].where = lightingBack->lights[k].where;
        m_fileLighting = m_parts.lighting;
        m_lightingFileLayout = lightingLayout;
    }
    m_sources[index(part)] = path;
    m_partDiagnostics[index(part)] = std::move(diagnostics);
    m_lastSaved[index(part)] = bytes;
    return rl::success();
}

}  // namespace rasterlab
