// SPDX-License-Identifier: MIT
#include <osgVis/core/scene/Walk.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace osgVis::core
{
namespace
{
const char* const Magic = "osgvis-walk";
constexpr int Version = 1;

// Reports "<source>:<line>: message".
class LineReader
{
public:
    LineReader(std::istream& in, const std::string& source) : _in(in), _source(source) {}

    // Next line with content, split into tokens ('#' starts a comment); false at the end.
    bool next(std::vector<std::string>& tokens)
    {
        std::string line;
        while (std::getline(_in, line))
        {
            ++_line;
            const std::size_t hash = line.find('#');
            if (hash != std::string::npos)
                line.erase(hash);
            std::istringstream words(line);
            tokens.clear();
            for (std::string w; words >> w;)
                tokens.push_back(w);
            if (!tokens.empty())
                return true;
        }
        if (_in.bad())
            fail("read error");
        return false;
    }

    [[noreturn]] void fail(const std::string& what) const
    {
        // note: an empty input reports line 1, where the header was expected.
        throw WalkError(_source + ":" + std::to_string(std::max(_line, 1)) + ": " + what);
    }

    double number(const std::string& token) const
    {
        const char* begin = token.c_str();
        char* end = nullptr;
        errno = 0;
        const double value = std::strtod(begin, &end);
        if (end == begin || *end != '\0')
            fail("'" + token + "' is not a number");
        if (!std::isfinite(value) || errno == ERANGE)
            fail("'" + token + "' is not a finite number");
        return value;
    }

    unsigned positiveInteger(const std::string& token) const
    {
        const char* begin = token.c_str();
        char* end = nullptr;
        errno = 0;
        const long long value = std::strtoll(begin, &end, 10);
        if (end == begin || *end != '\0' || errno == ERANGE)
            fail("'" + token + "' is not an integer");
        if (value <= 0 || value > 1000000)
            fail("size must be between 1 and 1000000, got " + token);
        return static_cast<unsigned>(value);
    }

    void expectFields(const std::vector<std::string>& tokens, std::size_t values, const std::string& what) const
    {
        if (tokens.size() != values + 1)
            fail("'" + what + "' expects " + std::to_string(values) + " values, got " +
                 std::to_string(tokens.size() - 1));
    }

    int line() const { return _line; }

private:
    std::istream& _in;
    const std::string& _source;
    int _line = 0;
};

void parseProjection(const LineReader& reader, const std::vector<std::string>& tokens, WalkProjection& p)
{
    if (tokens.size() < 2)
        reader.fail("'projection' expects a kind: perspective, frustum or ortho");
    const std::string& kind = tokens[1];
    if (kind == "perspective")
    {
        if (tokens.size() != 3)
            reader.fail("'projection perspective' expects 1 value (fovY degrees), got " +
                        std::to_string(tokens.size() - 2));
        p.kind = WalkProjection::Kind::Perspective;
        p.fovY = reader.number(tokens[2]);
        if (!(p.fovY > 0.0 && p.fovY < 180.0))
            reader.fail("perspective fovY must be in (0, 180) degrees, got " + tokens[2]);
        return;
    }
    if (kind != "frustum" && kind != "ortho")
        reader.fail("unknown projection '" + kind + "' (expected perspective, frustum or ortho)");
    if (tokens.size() != 6)
        reader.fail("'projection " + kind + "' expects 4 values (left right bottom top), got " +
                    std::to_string(tokens.size() - 2));
    p.kind = kind == "frustum" ? WalkProjection::Kind::Frustum : WalkProjection::Kind::Ortho;
    p.left = reader.number(tokens[2]);
    p.right = reader.number(tokens[3]);
    p.bottom = reader.number(tokens[4]);
    p.top = reader.number(tokens[5]);
    if (!(p.left < p.right) || !(p.bottom < p.top))
        reader.fail("projection " + kind + " needs left < right and bottom < top");
}

WalkKey parseView(const LineReader& reader, const std::vector<std::string>& tokens)
{
    reader.expectFields(tokens, 10, "view");
    double v[10];
    for (int i = 0; i < 10; ++i)
        v[i] = reader.number(tokens[i + 1]);
    WalkKey key;
    key.time = v[0];
    key.eye = Vec3(v[1], v[2], v[3]);
    key.center = Vec3(v[4], v[5], v[6]);
    key.up = Vec3(v[7], v[8], v[9]);
    const Vec3 direction = key.center - key.eye;
    if (glm::length(direction) == 0.0)
        reader.fail("view eye equals center");
    const double upLength = glm::length(key.up);
    if (upLength == 0.0 || glm::length(glm::cross(direction, key.up)) <= 1e-12 * glm::length(direction) * upLength)
        reader.fail("view up vector is zero or parallel to the view direction");
    return key;
}

// Shortest decimal text that reads back as exactly `value`.
std::string formatNumber(double value)
{
    std::ostringstream out;
    out.imbue(std::locale::classic());
    for (int precision = 6; precision <= 17; ++precision)
    {
        out.str({});
        out.precision(precision);
        out << value;
        if (std::strtod(out.str().c_str(), nullptr) == value)
            break;
    }
    return out.str();
}
} // namespace

Mat4 WalkProjection::matrix(double aspect) const
{
    switch (kind)
    {
    case Kind::Frustum:
        return glm::frustum(left, right, bottom, top, zNear, zFar);
    case Kind::Ortho:
        return glm::ortho(left, right, bottom, top, zNear, zFar);
    case Kind::Perspective:
    default:
        return glm::perspective(glm::radians(fovY), aspect, zNear, zFar);
    }
}

Mat4 WalkKey::viewMatrix() const
{
    return glm::lookAt(eye, center, up);
}

Walk Walk::parse(std::istream& in, const std::string& sourceName)
{
    LineReader reader(in, sourceName);
    std::vector<std::string> tokens;
    if (!reader.next(tokens))
        reader.fail(std::string("missing header '") + Magic + " " + std::to_string(Version) + "'");
    if (tokens[0] != Magic)
        reader.fail(std::string("missing header '") + Magic + " " + std::to_string(Version) + "', got '" +
                    tokens[0] + "'");
    if (tokens.size() != 2)
        reader.fail(std::string("header expects '") + Magic + " <version>'");
    if (tokens[1] != std::to_string(Version))
        reader.fail("unsupported walk version '" + tokens[1] + "' (expected " + std::to_string(Version) + ")");

    Walk walk;
    bool haveSize = false, haveProjection = false, haveClip = false;
    const auto once = [&](bool& seen, const std::string& keyword) {
        if (seen)
            reader.fail("duplicate '" + keyword + "'");
        seen = true;
    };
    while (reader.next(tokens))
    {
        const std::string& keyword = tokens[0];
        if (keyword == "size")
        {
            once(haveSize, keyword);
            reader.expectFields(tokens, 2, keyword);
            walk.width = reader.positiveInteger(tokens[1]);
            walk.height = reader.positiveInteger(tokens[2]);
        }
        else if (keyword == "projection")
        {
            once(haveProjection, keyword);
            // note: keeps the clip distances that may already have been read.
            WalkProjection p = walk.projection;
            parseProjection(reader, tokens, p);
            walk.projection = p;
        }
        else if (keyword == "clip")
        {
            once(haveClip, keyword);
            reader.expectFields(tokens, 2, keyword);
            const double zNear = reader.number(tokens[1]);
            const double zFar = reader.number(tokens[2]);
            if (!(zNear > 0.0) || !(zFar > zNear))
                reader.fail("clip needs 0 < near < far, got near " + tokens[1] + " far " + tokens[2]);
            walk.projection.zNear = zNear;
            walk.projection.zFar = zFar;
        }
        else if (keyword == "view")
        {
            const WalkKey key = parseView(reader, tokens);
            if (!walk.keys.empty() && !(key.time > walk.keys.back().time))
                reader.fail("view time " + tokens[1] + " is not after the previous view time " +
                            formatNumber(walk.keys.back().time));
            walk.keys.push_back(key);
        }
        else
        {
            reader.fail("unknown keyword '" + keyword + "'");
        }
    }
    if (!haveSize)
        reader.fail("missing 'size'");
    if (!haveProjection)
        reader.fail("missing 'projection'");
    if (!haveClip)
        reader.fail("missing 'clip'");
    if (walk.keys.empty())
        reader.fail("walk has no views");
    return walk;
}

Walk Walk::load(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw WalkError("cannot open walk file '" + path + "'");
    return parse(in, path);
}

void Walk::write(std::ostream& out) const
{
    const auto n = formatNumber;
    out << Magic << ' ' << Version << '\n';
    out << "size " << width << ' ' << height << '\n';
    switch (projection.kind)
    {
    case WalkProjection::Kind::Perspective:
        out << "projection perspective " << n(projection.fovY) << '\n';
        break;
    case WalkProjection::Kind::Frustum:
    case WalkProjection::Kind::Ortho:
        out << "projection " << (projection.kind == WalkProjection::Kind::Frustum ? "frustum " : "ortho ")
            << n(projection.left) << ' ' << n(projection.right) << ' ' << n(projection.bottom) << ' '
            << n(projection.top) << '\n';
        break;
    }
    out << "clip " << n(projection.zNear) << ' ' << n(projection.zFar) << '\n';
    out << "# view time  eye x y z  center x y z  up x y z\n";
    for (const WalkKey& k : keys)
    {
        out << "view " << n(k.time) << "  " << n(k.eye.x) << ' ' << n(k.eye.y) << ' ' << n(k.eye.z) << "  "
            << n(k.center.x) << ' ' << n(k.center.y) << ' ' << n(k.center.z) << "  " << n(k.up.x) << ' '
            << n(k.up.y) << ' ' << n(k.up.z) << '\n';
    }
}

void Walk::save(const std::string& path) const
{
    std::ofstream out(path);
    if (!out)
        throw WalkError("cannot write walk file '" + path + "'");
    write(out);
    out.flush();
    if (!out)
        throw WalkError("cannot write walk file '" + path + "'");
}
} // namespace osgVis::core
