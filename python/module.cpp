// The Python module scalecert: exact numbers in and out as fractions.Fraction.
#include <array>
#include <scalecert/scalecert.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

// Families of scenes (golden with a family) come from the campaign library, which needs no
// floating-point library; everything else goes through the public header.

#include <cmath>
#include <functional>
#include <cstdint>
#include <map>
#include <optional>
#include <set>

namespace py = pybind11;
using scalecert::Rational;

namespace {

// Integers cross between GMP and Python as bytes (mpz_export / int.from_bytes, int.to_bytes /
// mpz_import), never as decimal text: CPython 3.11 refuses int(str) and str(int) past 4,300 digits,
// and exact answers have more.
py::object pyint(const mpz_class& z) {
    if (z.fits_slong_p()) return py::int_(z.get_si());
    static const py::object* from_bytes = new py::object(
        py::reinterpret_borrow<py::object>(reinterpret_cast<PyObject*>(&PyLong_Type)).attr("from_bytes"));
    std::string buf((mpz_sizeinbase(z.get_mpz_t(), 2) + 7) / 8, '\0');
    size_t count = 0;
    mpz_export(buf.data(), &count, -1, 1, 0, 0, z.get_mpz_t());  // |z|, least significant byte first
    buf.resize(count);
    py::object v = (*from_bytes)(py::bytes(buf), "little");
    if (sgn(z) < 0) v = py::reinterpret_steal<py::object>(PyNumber_Negative(v.ptr()));
    if (!v) throw py::error_already_set();
    return v;
}

// Bits of an integer read from Python: those of 10^100000, the largest number a text may write
// (README "Limits": 100,000 characters, exponent within ±100,000).
constexpr size_t kMaxIntBits = 16384;  // as for text: limits.hpp, kMaxNumberBits

// A Python int (or anything with __index__) as a GMP integer, through its bytes.
mpz_class mpz_of(const py::handle& h) {
    py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(h.ptr()));
    if (!i) throw py::error_already_set();
    int overflow = 0;
    const long small = PyLong_AsLongAndOverflow(i.ptr(), &overflow);
    if (!overflow) {
        if (small == -1 && PyErr_Occurred()) throw py::error_already_set();
        return mpz_class(small);
    }
    const size_t bits = i.attr("bit_length")().cast<size_t>();
    if (bits > kMaxIntBits)
        throw scalecert::InputError("an integer of " + std::to_string(bits) + " bits, more than " +
                                    std::to_string(kMaxIntBits) + " (the limit for one number, as for text)");
    const bool negative = overflow < 0;
    py::object a = py::reinterpret_steal<py::object>(PyNumber_Absolute(i.ptr()));
    if (!a) throw py::error_already_set();
    const std::string b = a.attr("to_bytes")((bits + 7) / 8, "little").cast<std::string>();
    mpz_class z;
    mpz_import(z.get_mpz_t(), b.size(), -1, 1, 0, 0, b.data());
    if (negative) z = -z;
    return z;
}

py::object fraction(const Rational& q) {
    static const py::object* F = new py::object(py::module_::import("fractions").attr("Fraction"));
    return (*F)(pyint(q.get_num()), pyint(q.get_den()));
}

py::tuple fractions(const scalecert::Point& p) {
    return py::make_tuple(fraction(p[0]), fraction(p[1]), fraction(p[2]));
}

// int, fractions.Fraction, decimal.Decimal, numpy integers and floats, decimal strings ("0.1" is
// 1/10, "3/7"), and floats at their exact binary value.
// Whether h has the attribute: as py::hasattr, but an error other than AttributeError raised
// while looking (a KeyboardInterrupt in a property) goes on instead of reading as "no".
bool has_attr(const py::handle& h, const char* name) {
    if (PyObject* r = PyObject_GetAttrString(h.ptr(), name)) {
        Py_DECREF(r);
        return true;
    }
    if (PyErr_ExceptionMatches(PyExc_AttributeError)) {
        PyErr_Clear();
        return false;
    }
    throw py::error_already_set();
}

// A Python str as UTF-8 (a lone surrogate cannot be: InputError, not pybind11's cast error).
std::string utf8(const py::handle& h, const std::string& what) {
    Py_ssize_t n = 0;
    const char* p = PyUnicode_AsUTF8AndSize(h.ptr(), &n);
    if (!p) {
        PyErr_Clear();
        throw scalecert::InputError(what + ": not valid text (it cannot be UTF-8)");
    }
    return std::string(p, static_cast<size_t>(n));
}

// Whether a Python error raised while reading an argument is the argument's fault (any Exception
// but MemoryError): then InputError; KeyboardInterrupt, SystemExit and MemoryError go on.
bool argument_error(const py::error_already_set& e) {
    return e.matches(PyExc_Exception) && !e.matches(PyExc_MemoryError);
}

// A float, Python's or numpy's (any float dtype).
bool is_float(const py::handle& h) {
    return py::isinstance<py::float_>(h) ||
           (has_attr(h, "dtype") && py::str(h.attr("dtype").attr("kind")).cast<std::string>() == "f");
}

// A float is read as `numbers` says (scalecert::held): its value, the float32 nearest it, or its
// shortest decimal as written.
Rational rational(const py::handle& h, const char* what, scalecert::Numbers numbers = scalecert::Numbers::Double) {
    try {
        if (py::isinstance<py::bool_>(h)) throw scalecert::InputError("a bool is not a number");
        if (has_attr(h, "ndim") && py::int_(h.attr("ndim")).cast<long>() != 0)
            throw scalecert::InputError("expected one number, not an array");
        if (py::isinstance<py::str>(h)) return scalecert::parse_rational(utf8(h, "text"));
        if (is_float(h)) {
            const double d = py::float_(h.cast<py::object>()).cast<double>();
            if (!std::isfinite(d)) throw scalecert::InputError("not a finite number");
            return scalecert::held(d, numbers);
        }
        if (has_attr(h, "numerator") && has_attr(h, "denominator")) {  // int, Fraction, numpy integers
            const mpz_class n = mpz_of(py::int_(h.attr("numerator"))), d = mpz_of(py::int_(h.attr("denominator")));
            if (sgn(d) == 0) throw scalecert::InputError("zero denominator");
            Rational q(n, d);
            q.canonicalize();
            return q;
        }
        if (py::isinstance(h, py::module_::import("decimal").attr("Decimal")))
            return scalecert::parse_rational(py::str(h).cast<std::string>());
    } catch (const scalecert::InputError& e) {
        throw scalecert::InputError(std::string(what) + ": " + e.what());
    } catch (const py::error_already_set& e) {
        // Errors about the value mean "not a number"; others (KeyboardInterrupt, MemoryError) go on.
        if (!argument_error(e)) throw;
        throw scalecert::InputError(std::string(what) + ": not a number");
    }
    throw scalecert::InputError(std::string(what) + ": not a number (int, Fraction, Decimal, float or decimal string)");
}

// A float beyond the float32 range, read under Numbers::Float32: a float32 program held an infinity.
bool beyond_float32(const py::handle& h, scalecert::Numbers numbers) {
    if (numbers != scalecert::Numbers::Float32 || !is_float(h)) return false;
    const double d = py::float_(h.cast<py::object>()).cast<double>();
    return std::isfinite(d) && !std::isfinite(static_cast<float>(d));
}

// A float (Python's or numpy's) that is NaN or infinite: a program's output that is no answer.
bool non_finite(const py::handle& h) {
    return is_float(h) && !std::isfinite(py::float_(h.cast<py::object>()).cast<double>());
}

py::list as_list(const py::handle& h, const std::string& what) {
    if (py::hasattr(h, "tolist")) {  // numpy arrays; a numpy scalar or 0-d array gives no list
        py::object l = h.attr("tolist")();
        if (py::isinstance<py::list>(l)) return py::reinterpret_borrow<py::list>(l);
        throw scalecert::InputError(what + ": expected a list");
    }
    if (py::isinstance<py::str>(h) || !py::isinstance<py::sequence>(h))
        throw scalecert::InputError(what + ": expected a list");
    return py::list(py::reinterpret_borrow<py::object>(h));
}

scalecert::Point point(const py::handle& h, const std::string& what,
                       scalecert::Numbers numbers = scalecert::Numbers::Double) {
    py::list l = as_list(h, what);
    if (l.size() != 3) throw scalecert::InputError(what + ": expected 3 coordinates");
    return {rational(l[0], what.c_str(), numbers), rational(l[1], what.c_str(), numbers),
            rational(l[2], what.c_str(), numbers)};
}

std::vector<scalecert::Point> points(const py::handle& h, const std::string& what,
                                     scalecert::Numbers numbers = scalecert::Numbers::Double) {
    std::vector<scalecert::Point> out;
    py::list l = as_list(h, what);
    for (size_t i = 0; i < l.size(); ++i) out.push_back(point(l[i], what + "[" + std::to_string(i) + "]", numbers));
    return out;
}

scalecert::Interval interval(const py::handle& h, const std::string& what,
                             scalecert::Numbers numbers = scalecert::Numbers::Double) {
    if (h.is_none()) return {};  // [1, 1]: the object as it is
    py::list l = as_list(h, what);
    if (l.size() != 2) throw scalecert::InputError(what + ": expected (lo, hi)");
    return {rational(l[0], what.c_str(), numbers), rational(l[1], what.c_str(), numbers)};
}

// numbers="double" | "float32" | "exact" (scalecert::Numbers).
scalecert::Numbers numbers_arg(const py::handle& h) {
    if (py::isinstance<py::str>(h)) {
        const std::string s = py::str(h).cast<std::string>();
        if (s == "double") return scalecert::Numbers::Double;
        if (s == "float32") return scalecert::Numbers::Float32;
        if (s == "exact") return scalecert::Numbers::Exact;
    }
    throw scalecert::InputError("numbers: expected 'double', 'float32' or 'exact', not " +
                                py::repr(h).cast<std::string>());
}

py::object json_loads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

// Arguments that are not numbers, checked here so that a wrong type is an InputError (one line)
// like every other bad argument, never pybind11's TypeError or a bare OverflowError.
// A path: a str or an os.PathLike giving one.
std::string type_name(const py::handle& h) { return utf8(py::str(py::type::of(h).attr("__name__")), "a type's name"); }
std::string path_arg(const py::handle& h, const char* what) {
    std::string path;
    if (py::isinstance<py::str>(h)) {
        path = utf8(h, what);
    } else {
        py::object p;
        try {
            p = py::module_::import("os").attr("fspath")(h);
        } catch (const py::error_already_set& e) {
            if (!argument_error(e)) throw;
        }
        if (!p || !py::isinstance<py::str>(p))
            throw scalecert::InputError(std::string(what) + ": expected a path (a str or os.PathLike), not " +
                                        type_name(h));
        path = utf8(p, what);
    }
    // (The C++ side would read the name up to the NUL: another file than the one named.)
    if (path.find('\0') != std::string::npos)
        throw scalecert::InputError(std::string(what) + ": a path with a NUL byte");
    return path;
}
std::string text_arg(const py::handle& h, const char* what) {
    if (!py::isinstance<py::str>(h))
        throw scalecert::InputError(std::string(what) + ": expected a str, not " + type_name(h));
    return utf8(h, what);
}
bool flag_arg(const py::handle& h, const char* what) {
    if (!py::isinstance<py::bool_>(h)) throw scalecert::InputError(std::string(what) + ": expected True or False");
    return h.cast<bool>();
}
// A whole number (an int or anything with __index__, not a bool) in [lo, hi]; `range` words the
// bounds for the message.
mpz_class whole_arg(const py::handle& h, const char* what, const mpz_class& lo, const mpz_class& hi,
                    const std::string& range) {
    const scalecert::InputError bad(std::string(what) + ": expected an int from " + range);
    if (py::isinstance<py::bool_>(h) || !has_attr(h, "__index__")) throw bad;
    mpz_class z;
    try {
        z = mpz_of(h);
    } catch (const scalecert::InputError&) {  // past the bits any number may have
        throw bad;
    } catch (const py::error_already_set& e) {  // an __index__ that raises, or returns no int
        if (!argument_error(e)) throw;
        throw bad;
    }
    if (z < lo || z > hi) throw bad;
    return z;
}
int count_arg(const py::handle& h, const char* what, long lo, long hi) {
    return static_cast<int>(whole_arg(h, what, lo, hi, std::to_string(lo) + " to " + std::to_string(hi)).get_si());
}
// Scene.golden's and golden's verticals= and offsets= (None: the default offsets); their ranges
// are the engine's to check.
scalecert::GoldenOptions golden_options(const py::handle& verticals, const py::handle& offsets) {
    scalecert::GoldenOptions o;
    o.verticals = count_arg(verticals, "verticals", 0, 1000);
    if (!offsets.is_none()) {
        if (!py::isinstance<py::sequence>(offsets) || py::isinstance<py::str>(offsets))
            throw scalecert::InputError("offsets: expected a list of K (pairs 2^-K away), e.g. [4, 12, 52]");
        o.offsets.clear();
        for (const py::handle& k : offsets) o.offsets.push_back(count_arg(k, "offsets[k]", 1, 1074));
    }
    return o;
}
unsigned long long seed_arg(const py::handle& h, const char* what) {
    static const mpz_class top = (mpz_class(1) << 64) - 1;
    const mpz_class z = whole_arg(h, what, 0, top, "0 to 2^64 - 1");
    unsigned long long v = 0;
    mpz_export(&v, nullptr, -1, sizeof v, 0, 0, z.get_mpz_t());
    return v;
}

// The document with every int (Python's, or numpy's through .tolist()) as its exact decimal
// string: json.dumps would write it as a JSON number, which certify-fp reads as the double a
// program held (2^53 + 1 would become 2^53), while Scene.certify reads an int exactly. Dicts,
// lists and tuples are copied; nesting deeper than a claims document's is refused.
py::object exact_ints(const py::handle& o, int depth) {
    if (depth > 32) throw scalecert::InputError("claims: nested more than 32 levels deep");
    if (py::isinstance<py::bool_>(o) || py::isinstance<py::str>(o) || py::isinstance<py::float_>(o) || o.is_none())
        return py::reinterpret_borrow<py::object>(o);
    if (py::isinstance<py::int_>(o)) return py::str(mpz_of(o).get_str(10));
    if (py::isinstance<py::dict>(o)) {
        py::dict d;
        for (const auto& kv : py::reinterpret_borrow<py::dict>(o)) d[kv.first] = exact_ints(kv.second, depth + 1);
        return d;
    }
    if (py::isinstance<py::list>(o) || py::isinstance<py::tuple>(o)) {
        py::list l;
        for (const py::handle& x : o) l.append(exact_ints(x, depth + 1));
        return l;
    }
    if (has_attr(o, "tolist") && has_attr(o, "dtype")) {  // numpy
        py::object r = o.attr("tolist")();
        if (!r.get_type().is(py::type::of(o))) return exact_ints(r, depth + 1);
        // A scalar with no Python counterpart (a long double): its exact value.
        if (has_attr(o, "as_integer_ratio")) {
            const py::tuple t = o.attr("as_integer_ratio")();
            return py::str(mpz_of(t[0]).get_str(10) + "/" + mpz_of(t[1]).get_str(10));
        }
    }
    return py::reinterpret_borrow<py::object>(o);
}

// Claims from Python: a str is a claims file's text; a dict is a scalecert-claims-1 document, and a
// list (or tuple) its claims. json.dumps writes a float as its shortest repr, which strtod reads
// back as the same double, so a float claims exactly the double it is; an int, a Fraction or a
// Decimal becomes an exact string ("12", "p/q"); numpy scalars and arrays become numbers and lists
// (.tolist()). NaN and infinity are written NaN and Infinity, which certify-fp reads as no answer.
std::string claims_text(const py::handle& c) {
    if (py::isinstance<py::str>(c)) return utf8(c, "claims");
    py::object doc;
    if (py::isinstance<py::dict>(c)) {
        doc = py::reinterpret_borrow<py::object>(c);
    } else if (py::isinstance<py::list>(c) || py::isinstance<py::tuple>(c)) {
        py::dict d;
        d["format"] = "scalecert-claims-1";
        d["claims"] = py::list(py::reinterpret_borrow<py::object>(c));
        doc = d;
    } else {
        throw scalecert::InputError("claims: expected a str (a claims file's text), a dict or a list of claim dicts");
    }
    try {
        doc = exact_ints(doc, 0);
    } catch (const py::error_already_set& e) {
        if (!argument_error(e)) throw;
        throw scalecert::InputError("claims: " + utf8(py::str(e.value()), "claims"));
    }
    py::object Fraction = py::module_::import("fractions").attr("Fraction");
    py::object Decimal = py::module_::import("decimal").attr("Decimal");
    py::cpp_function exact([Fraction, Decimal](const py::handle& o) -> py::object {
        if (py::isinstance(o, Fraction) || py::isinstance(o, Decimal)) return py::str(Fraction(o));
        if (has_attr(o, "tolist")) return o.attr("tolist")();
        throw scalecert::InputError("claims: " + py::repr(o).cast<std::string>() +
                                    " is not a number, string, list or dict");
    });
    try {
        return utf8(
            py::module_::import("json").attr("dumps")(doc, py::arg("default") = exact, py::arg("allow_nan") = true),
            "claims");
    } catch (const py::error_already_set& e) {
        if (!argument_error(e)) throw;
        const std::string what = utf8(py::str(e.value()), "claims");
        throw scalecert::InputError(what.rfind("claims: ", 0) == 0 ? what : "claims: " + what);
    }
}

// {"contact": "VE", "features": (P1's vertices, P2's)}, or {"contact": None} where nothing touches.
py::dict contact_dict(const std::optional<scalecert::Contact>& c) {
    py::dict d;
    if (!c) {
        d["contact"] = py::none();
        return d;
    }
    d["contact"] = scalecert::name(c->kind);
    d["features"] = py::make_tuple(c->verts1, c->verts2);
    return d;
}

// A scene with its analysis, built on first use.
struct PyScene {
    scalecert::Scene scene;
    mutable std::shared_ptr<const scalecert::Analysis> analysis;
    // How the scene's floats were read; rho1, rho2 and claims given later are read alike unless
    // a call says otherwise (certify's numbers=).
    scalecert::Numbers numbers = scalecert::Numbers::Double;
    const scalecert::Analysis& a() const {
        if (!analysis) analysis = std::make_shared<const scalecert::Analysis>(scene);
        return *analysis;
    }
};

// seeds = (s1, s2) or None; either may be None (the mean of the object's points).
std::array<std::optional<scalecert::Point>, 2> seeds_of(const py::handle& seeds, scalecert::Numbers numbers) {
    std::array<std::optional<scalecert::Point>, 2> s;
    if (!seeds.is_none()) {
        py::list l = as_list(seeds, "seeds");
        if (l.size() != 2) throw scalecert::InputError("seeds: expected (seed1, seed2); either may be None");
        for (int i = 0; i < 2; ++i)
            if (!l[i].is_none()) s[static_cast<size_t>(i)] = point(l[i], "seeds[" + std::to_string(i) + "]", numbers);
    }
    return s;
}

PyScene make_scene(const py::handle& p1, const py::handle& p2, const py::handle& i1, const py::handle& i2,
                   const py::handle& seeds, scalecert::Numbers numbers, const py::handle& radii = py::none()) {
    const auto s = seeds_of(seeds, numbers);
    if (!radii.is_none()) {
        // radii = (r1, r2): objects with a radius (a numpy pair, floats, Fractions, strings).
        const py::list l = as_list(radii, "radii");
        if (l.size() != 2) throw scalecert::InputError("radii: expected (r1, r2), each >= 0");
        const std::array<scalecert::Rational, 2> r{rational(l[0], "radii[0]", numbers),
                                                   rational(l[1], "radii[1]", numbers)};
        return PyScene{
            scalecert::Scene::with_radii(points(p1, "P1", numbers), points(p2, "P2", numbers), r,
                                         interval(i1, "I1", numbers), interval(i2, "I2", numbers), s[0], s[1]),
            nullptr, numbers};
    }
    return PyScene{scalecert::Scene(points(p1, "P1", numbers), points(p2, "P2", numbers), interval(i1, "I1", numbers),
                                    interval(i2, "I2", numbers), s[0], s[1]),
                   nullptr, numbers};
}

py::dict curve_dict(const scalecert::Curve& c) {
    py::list pieces, switches;
    for (const scalecert::Piece& p : c.pieces) {
        py::dict d = contact_dict(p.contact);
        d["rho1"] = py::make_tuple(fraction(p.from), fraction(p.to));
        d["slope"] = fraction(p.slope);
        d["intercept"] = fraction(p.intercept);
        d["normal"] = fractions(p.normal);
        pieces.append(d);
    }
    for (const scalecert::SwitchPoint& s : c.switches) {
        py::dict d = contact_dict(s.contact);
        d["rho1"] = fraction(s.rho1);
        d["rho2"] = fraction(s.rho2);
        switches.append(d);
    }
    py::dict out;
    out["pieces"] = pieces;
    out["switch_points"] = switches;
    out["growth_distance"] = fraction(c.growth.value);
    out["growth_distance_in_rectangle"] = c.growth.in_rectangle;
    return out;
}

}  // namespace

using namespace pybind11::literals;

// A claimed verdict's word (scalecert::name), or none.
std::optional<scalecert::ClaimedVerdict> claimed_verdict(const std::string& v) {
    using scalecert::ClaimedVerdict;
    for (ClaimedVerdict c : {ClaimedVerdict::Separated, ClaimedVerdict::Touching, ClaimedVerdict::Overlapping,
                             ClaimedVerdict::Intersecting, ClaimedVerdict::NotOverlapping})
        if (v == scalecert::name(c)) return c;
    return std::nullopt;
}

// Scene.certify: claims of one kind from arrays, judged by the typed API (Analysis::certify)
// on convex objects and on objects made of parts.
using CertifyFn =
    std::function<scalecert::Judgements(const std::vector<scalecert::Claim>&, const scalecert::ClaimOptions&)>;
py::dict certify_arrays(const CertifyFn& certify, const std::string& kind, const py::handle& rho1,
                        const py::handle& rho2, const py::handle& value, const py::handle& closest,
                        const py::handle& direction, const py::handle& normal, const py::handle& offset,
                        const py::handle& point_, const py::handle& verdict, const py::handle& tolerance,
                        const py::handle& abs_tolerance, bool certificate, bool fractions, scalecert::Numbers numbers,
                        const py::handle& parts, const py::handle& pose1, const py::handle& pose2, bool of_parts) {
    using scalecert::ClaimKind;
    static const std::map<std::string, ClaimKind> kinds = {{"distance", ClaimKind::Distance},
                                                           {"penetration_depth", ClaimKind::PenetrationDepth},
                                                           {"verdict", ClaimKind::Verdict},
                                                           {"separating_plane", ClaimKind::SeparatingPlane},
                                                           {"witness_point", ClaimKind::WitnessPoint},
                                                           {"signed_distance", ClaimKind::SignedDistance}};
    const auto k = kinds.find(kind);
    if (k == kinds.end())
        throw scalecert::InputError(
            "certify: unknown kind '" + kind +
            "' (distance, penetration_depth, signed_distance, verdict, separating_plane, witness_point)");
    const py::list r1 = as_list(rho1, "rho1"), r2 = as_list(rho2, "rho2");
    const size_t n = r1.size();
    // An array argument with one row per claim, or none.
    auto rows = [&](const py::handle& h, const char* what, bool needed) -> std::optional<py::list> {
        if (h.is_none()) {
            if (needed)
                throw scalecert::InputError(std::string("certify: ") + what + " is required for kind '" + kind + "'");
            return std::nullopt;
        }
        py::list l = as_list(h, what);
        if (l.size() != n)
            throw scalecert::InputError(std::string("certify: ") + what + " has " + std::to_string(l.size()) +
                                        " rows, rho1 has " + std::to_string(n));
        return l;
    };
    if (r2.size() != n)
        throw scalecert::InputError("certify: rho2 has " + std::to_string(r2.size()) + " rows, rho1 has " +
                                    std::to_string(n));
    const ClaimKind ck = k->second;
    const bool measure =
        ck == ClaimKind::Distance || ck == ClaimKind::PenetrationDepth || ck == ClaimKind::SignedDistance;
    const auto values = rows(value, "value", measure);
    const auto cl = rows(closest, "closest", false), dir = rows(direction, "direction", false),
               nor = rows(normal, "normal", ck == ClaimKind::SeparatingPlane), off = rows(offset, "offset", false),
               pts = rows(point_, "point", ck == ClaimKind::WitnessPoint), prs = rows(parts, "parts", false),
               ps1 = rows(pose1, "pose1", false), ps2 = rows(pose2, "pose2", false);
    std::optional<py::list> verdicts;
    if (ck == ClaimKind::Verdict) {
        if (verdict.is_none()) throw scalecert::InputError("certify: verdict is required for kind 'verdict'");
        verdicts = py::isinstance<py::str>(verdict) ? py::list() : rows(verdict, "verdict", true);
    }
    // The first argument the kind does not use, named.
    const char* unused = cl && ck != ClaimKind::Distance                                               ? "closest"
                         : dir && ck != ClaimKind::PenetrationDepth                                    ? "direction"
                         : prs && ck != ClaimKind::PenetrationDepth && ck != ClaimKind::SignedDistance ? "parts"
                         : (nor || off) && ck != ClaimKind::SeparatingPlane ? (nor ? "normal" : "offset")
                         : pts && ck != ClaimKind::WitnessPoint             ? "point"
                         : values && !measure                               ? "value"
                                                                            : nullptr;
    if (unused)
        throw scalecert::InputError(std::string("certify: ") + unused + ": kind '" + kind + "' does not use it");
    std::vector<scalecert::Claim> claims(n);
    for (size_t i = 0; i < n; ++i) {
        const std::string at = "[" + std::to_string(i) + "]";
        scalecert::Claim& c = claims[i];
        c.kind = ck;
        c.rho1 = rational(r1[i], ("rho1" + at).c_str(), numbers);
        c.rho2 = rational(r2[i], ("rho2" + at).c_str(), numbers);
        // The program's answers: a NaN or an infinity there is no answer (the claim is wrong).
        auto answer = [&](const py::handle& h, const char* field, Rational& q) {
            if (non_finite(h) || beyond_float32(h, numbers)) {
                if (c.no_answer.empty()) c.no_answer = field;
            } else {
                q = rational(h, (field + at).c_str(), numbers);
            }
        };
        auto answer_point = [&](const py::handle& h, const char* field, const std::string& what, scalecert::Point& p) {
            const py::list l = as_list(h, what);
            auto none = [&](const py::handle& x) { return non_finite(x) || beyond_float32(x, numbers); };
            if (l.size() == 3 && (none(l[0]) || none(l[1]) || none(l[2]))) {
                if (c.no_answer.empty()) c.no_answer = field;
            } else {
                p = point(h, what, numbers);
            }
        };
        if (values) answer((*values)[i], "value", c.value);
        if (cl) {
            const py::list two = as_list((*cl)[i], "closest" + at);
            if (two.size() != 2) throw scalecert::InputError("certify: closest" + at + ": expected two points");
            auto& pq = c.closest.emplace();
            answer_point(two[0], "closest", "closest" + at + "[0]", pq[0]);
            answer_point(two[1], "closest", "closest" + at + "[1]", pq[1]);
        }
        if (dir) answer_point((*dir)[i], "direction", "direction" + at, c.direction.emplace());
        // A pose is the program's question: each (3, 4), [R | t] by rows, read as the rhos are.
        for (size_t k = 0; k < 2; ++k) {
            const std::optional<py::list>& ps = k ? ps2 : ps1;
            if (!ps) continue;
            const std::string what = std::string(k ? "pose2" : "pose1") + at;
            const py::list rows3 = as_list((*ps)[i], what);
            if (rows3.size() != 3)
                throw scalecert::InputError("certify: " + what + ": expected 3 rows [r1, r2, r3, t]");
            scalecert::Pose& m = (k ? c.pose2 : c.pose1).emplace();
            for (size_t r = 0; r < 3; ++r) {
                const std::string wr = what + "[" + std::to_string(r) + "]";
                const py::list row = as_list(rows3[r], wr);
                if (row.size() != 4)
                    throw scalecert::InputError("certify: " + wr + ": expected 4 numbers [r1, r2, r3, t]");
                for (size_t q = 0; q < 4; ++q) m[r][q] = rational(row[q], wr.c_str(), numbers);
            }
        }
        if (prs) {
            const py::list two = as_list((*prs)[i], "parts" + at);
            if (two.size() != 2)
                throw scalecert::InputError("certify: parts" + at + ": expected (part of P1, part of P2)");
            auto& kj = c.parts.emplace();
            for (size_t k = 0; k < 2; ++k)
                kj[k] = count_arg(two[k], ("parts" + at + "[" + std::to_string(k) + "]").c_str(), 0, 2147483647L);
        }
        if (nor) answer_point((*nor)[i], "normal", "normal" + at, c.normal);
        if (off) answer((*off)[i], "offset", c.offset.emplace());
        if (pts) answer_point((*pts)[i], "point", "point" + at, c.point);
        if (verdicts) {
            const std::string v = utf8(py::str(verdicts->empty() ? verdict : (*verdicts)[i]), "certify: verdict" + at);
            const std::optional<scalecert::ClaimedVerdict> cv = claimed_verdict(v);
            if (!cv)
                throw scalecert::InputError("certify: verdict" + at + ": '" + v +
                                            "' (separated, touching, overlapping, intersecting)");
            c.verdict = *cv;
        }
    }
    scalecert::ClaimOptions opt;
    opt.tolerance = rational(tolerance, "tolerance");
    opt.abs_tolerance = rational(abs_tolerance, "abs_tolerance");
    opt.certificate = certificate;
    scalecert::Judgements j;
    {
        py::gil_scoped_release release;
        j = certify(claims, opt);
    }
    py::module_ np = py::module_::import("numpy");
    py::list right, exact, rel, vr, cr, dr, sq, rs, ev, why, pairs, pair_names;
    for (const scalecert::Judgement& g : j.items) {
        right.append(g.right);
        why.append(g.reason);
        exact.append(g.exact_squared ? g.exact : NAN);
        rel.append(g.exact_squared ? g.rel_error : NAN);
        // (A depth claimed of a separated pair has no parts: each is wrong.)
        vr.append(g.value_right.value_or(ck == ClaimKind::SignedDistance && g.right));  // its one answer
        cr.append(g.closest_right.value_or(false));
        dr.append(g.direction_right.value_or(false));
        if (fractions) sq.append(g.exact_squared ? fraction(*g.exact_squared) : py::object(py::none()));
        if (fractions) rs.append(g.radius_sum ? fraction(*g.radius_sum) : py::object(py::none()));
        pairs.append(py::make_tuple(g.part1, g.part2));
        pair_names.append(py::make_tuple(g.part1_name, g.part2_name));
        if (g.exact_verdict) ev.append(scalecert::name(*g.exact_verdict));
    }
    py::dict d;
    d["right"] = np.attr("array")(right, "dtype"_a = "bool");
    d["reason"] = why;  // "" unless the claim held no answer ("value: not a number")
    if (measure) {
        d["exact"] = np.attr("array")(exact, "dtype"_a = "float64");
        d["rel_error"] = np.attr("array")(rel, "dtype"_a = "float64");
        d["value_right"] = np.attr("array")(vr, "dtype"_a = "bool");
    }
    if (cl) d["closest_right"] = np.attr("array")(cr, "dtype"_a = "bool");
    if (dir) d["direction_right"] = np.attr("array")(dr, "dtype"_a = "bool");
    if (fractions && measure) d["exact_squared"] = sq;  // on objects with a radius, the hulls'
    if (fractions && measure) d["radius_sum"] = rs;     // R (None without radii): exact = ±√exact_squared − R
    if (ck == ClaimKind::Verdict || ck == ClaimKind::SignedDistance) d["exact_verdict"] = ev;
    if (of_parts) {  // the part pair each exact answer rests on, (-1, -1) for none, and their names
        d["exact_parts"] = np.attr("array")(pairs, "dtype"_a = "int64").attr("reshape")(n, 2);
        d["exact_part_names"] = pair_names;
    }
    d["wrong"] = j.wrong;
    if (certificate) d["certificate"] = j.certificate;
    return d;
}

// classify over two one-dimensional arrays: f(rho1, rho2) without the GIL, as an int8 array.
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
// A list or array of real numbers as doubles; anything else (strings, complex numbers, objects)
// is an InputError, not pybind's TypeError.
DoubleArray doubles_of(const py::handle& h, const char* what, const char* who = "classify") {
    const py::object np = py::module_::import("numpy");
    py::object a = np.attr("asarray")(h);
    std::string kind = py::str(a.attr("dtype").attr("kind")).cast<std::string>();
    if (kind == "O") {  // Fractions, Decimals, ints past 64 bits, mixed: as doubles, if they are real numbers
        try {
            py::object f = np.attr("asarray")(a, py::arg("dtype") = np.attr("float64"));
            // Each must be exactly that double: classify judges the doubles a program holds, and
            // an int or a Fraction that is not one would be judged at another value.
            const py::list orig = a.attr("ravel")().attr("tolist")(), as_f = f.attr("ravel")().attr("tolist")();
            py::object Fraction = py::module_::import("fractions").attr("Fraction");
            for (size_t i = 0; i < orig.size(); ++i)
                if (!py::isinstance<py::float_>(orig[i]) && !Fraction(orig[i]).equal(Fraction(as_f[i])))
                    throw scalecert::InputError(std::string(who) + ": " + what + "[" + std::to_string(i) +
                                                "]: " + py::repr(orig[i]).cast<std::string>().substr(0, 40) +
                                                " is not a double (classify takes doubles)");
            a = f;
            kind = "f";
        } catch (const py::error_already_set& e) {
            if (!e.matches(PyExc_TypeError) && !e.matches(PyExc_ValueError) && !e.matches(PyExc_OverflowError)) throw;
        }
    }
    if (kind != "f" && kind != "i" && kind != "u")
        throw scalecert::InputError(std::string(who) + ": " + what +
                                    ": expected real numbers (an array or list of floats or ints)");
    // Integers, and floats wider than doubles (numpy's longdouble): each must be a double exactly
    // (beyond 2^53 not every integer is; 0.1 as a long double is not the double 0.1).
    if (kind != "f" || py::cast<size_t>(a.attr("dtype").attr("itemsize")) > 8) {
        py::object f = np.attr("asarray")(a, py::arg("dtype") = np.attr("float64"));
        py::object back = f.attr("astype")(a.attr("dtype"));
        py::object differ = np.attr("not_equal")(back, a);
        if (kind != "f")  // (an int64 past 2^63 - 2^10 rounds to 2^63, which wraps back)
            differ = np.attr("logical_or")(differ, np.attr("greater_equal")(np.attr("abs")(f), 9.2e18));
        py::object bad = np.attr("flatnonzero")(differ);
        if (py::len(bad) > 0) {
            const size_t i = py::cast<size_t>(bad[py::int_(0)]);
            throw scalecert::InputError(std::string(who) + ": " + what + "[" + std::to_string(i) +
                                        "]: " + py::repr(a.attr("ravel")()[py::int_(i)]).cast<std::string>() +
                                        " is not a double (classify takes doubles)");
        }
        a = f;
    }
    return DoubleArray::ensure(a);
}
template <class F>
py::array_t<std::int8_t> classify_array(const py::handle& h1, const py::handle& h2, F&& f) {
    const DoubleArray r1 = doubles_of(h1, "rho1"), r2 = doubles_of(h2, "rho2");
    if (r1.ndim() != 1 || r2.ndim() != 1) throw scalecert::InputError("classify: one-dimensional arrays expected");
    const std::vector<double> a(r1.data(), r1.data() + r1.size()), b(r2.data(), r2.data() + r2.size());
    std::vector<scalecert::Verdict> v;
    {
        py::gil_scoped_release free;
        v = f(a, b);
    }
    py::array_t<std::int8_t> out(static_cast<py::ssize_t>(v.size()));
    auto w = out.mutable_unchecked<1>();
    for (size_t i = 0; i < v.size(); ++i) w(static_cast<py::ssize_t>(i)) = static_cast<std::int8_t>(v[i]);
    return out;
}

// The scene's notes (Scene::notes) as UserWarnings; a warning made an error (-W error) raises.
PyScene warn_notes(PyScene s) {
    for (const std::string& n : s.scene.notes())
        if (PyErr_WarnEx(PyExc_UserWarning, n.c_str(), 1) != 0) throw py::error_already_set();
    return s;
}

namespace {

// Scene.from_parts: P1, P2 lists of parts; radii = (radii1, radii2), each None or a radius a part.
PyScene parts_scene(const py::handle& p1, const py::handle& p2, const py::handle& i1, const py::handle& i2,
                    const py::handle& seeds, scalecert::Numbers numbers, const py::handle& radii) {
    std::vector<std::vector<scalecert::Point>> parts[2];
    std::array<std::vector<scalecert::Rational>, 2> part_radii;
    const char* names[2] = {"P1", "P2"};
    const py::handle ps[2] = {p1, p2};
    for (int i = 0; i < 2; ++i) {
        py::list l = as_list(ps[i], names[i]);
        for (size_t k = 0; k < l.size(); ++k)
            parts[i].push_back(points(l[k], std::string(names[i]) + "[" + std::to_string(k) + "]", numbers));
    }
    if (!radii.is_none()) {
        const py::list l = as_list(radii, "radii");
        if (l.size() != 2) throw scalecert::InputError("radii: expected (radii1, radii2), either None");
        for (size_t i = 0; i < 2; ++i) {
            if (l[i].is_none()) continue;
            const std::string what = "radii[" + std::to_string(i) + "]";
            const py::list r = as_list(l[i], what);
            for (size_t k = 0; k < r.size(); ++k)
                part_radii[i].push_back(rational(r[k], (what + "[" + std::to_string(k) + "]").c_str(), numbers));
        }
    }
    const auto s = seeds_of(seeds, numbers);
    return PyScene{scalecert::Scene::from_parts(std::move(parts[0]), std::move(parts[1]), interval(i1, "I1", numbers),
                                                interval(i2, "I2", numbers), s[0], s[1], std::move(part_radii)),
                   nullptr, numbers};
}

// The enum Verdict: classify()'s int8 codes, and query()'s verdict.
void bind_verdict(py::module_& m) {
    py::enum_<scalecert::Verdict>(m, "Verdict", "classify() returns these as int8 codes")
        .value("Separated", scalecert::Verdict::Separated)
        .value("Touching", scalecert::Verdict::Touching)
        .value("Overlapping", scalecert::Verdict::Overlapping);
}

// Scene's constructors: from points, from parts, from a scene file, from mesh files.
void bind_scene_construction(py::class_<PyScene>& scene) {
    scene
        .def(py::init([](const py::handle& p1, const py::handle& p2, const py::handle& i1, const py::handle& i2,
                         const py::handle& seeds, const py::handle& numbers, const py::handle& radii) {
                 return make_scene(p1, p2, i1, i2, seeds, numbers_arg(numbers), radii);
             }),
             py::arg("P1"), py::arg("P2"), py::arg("I1") = py::none(), py::arg("I2") = py::none(),
             py::arg("seeds") = py::none(), py::arg("numbers") = "double", py::arg("radii") = py::none(),
             "Two convex objects. Vertices as lists or numpy arrays of ints, Fractions, Decimals, decimal strings or "
             "floats; I1, I2 = (lo, hi), default (1, 1): no scaling; seeds = (s1, s2), default the means. A float is "
             "read as numbers says: "
             "'double' (its exact value), 'float32' (the float nearest it, as a float32 program holds it) or 'exact' "
             "(its shortest decimal, as written: 0.1 is 1/10); str, Fraction, Decimal and int are exact always. "
             "radii = (r1, r2), each >= 0: objects with a radius, every point within r of the hull of the vertices "
             "(one vertex: a sphere; two: a capsule), judged at any pair (the curve is refused).")
        .def_static(
            "from_parts",
            [](const py::handle& p1, const py::handle& p2, const py::handle& i1, const py::handle& i2,
               const py::handle& seeds, const py::handle& numbers_,
               const py::handle& radii) { return parts_scene(p1, p2, i1, i2, seeds, numbers_arg(numbers_), radii); },
            py::arg("P1"), py::arg("P2"), py::arg("I1") = py::none(), py::arg("I2") = py::none(),
            py::arg("seeds") = py::none(), py::arg("numbers") = "double", py::arg("radii") = py::none(),
            "Two objects made of convex parts: P1, P2 lists of parts, each a list of vertices (numbers as for "
            "Scene); seeds = (s1, s2), either may be None: the mean of all that object's vertices. radii = "
            "(radii1, radii2), either None: a radius >= 0 for each part of that object (a list or numpy array), "
            "each part every point within its radius of its hull (one vertex: a sphere).")
        .def_static(
            "sphere_set",
            [](const py::handle& centres, const py::handle& radii, const py::handle& other,
               const py::handle& other_radius, const py::handle& i1, const py::handle& i2, const py::handle& seeds,
               const py::handle& numbers_) {
                // A part per centre (one point) with its radius, against one convex object.
                const scalecert::Numbers numbers = numbers_arg(numbers_);
                py::list spheres;
                for (const py::handle c : as_list(centres, "centres")) spheres.append(py::make_tuple(c));
                py::list others;
                others.append(other);
                py::list other_radii;
                other_radii.append(other_radius);
                return parts_scene(spheres, others, i1, i2, seeds, numbers, py::make_tuple(radii, other_radii));
            },
            py::arg("centres"), py::arg("radii"), py::arg("other"), py::arg("other_radius") = 0,
            py::arg("I1") = py::none(), py::arg("I2") = py::none(), py::arg("seeds") = py::none(),
            py::arg("numbers") = "double",
            "A sphere set (centres: an n x 3 array, radii: n radii > 0), one object of n parts, against the convex "
            "hull of `other`'s vertices with other_radius >= 0; the rest as for from_parts.")
        .def_static(
            "load",
            [](const py::handle& path, const py::handle& numbers_) {
                const scalecert::Numbers numbers = numbers_arg(numbers_);
                return warn_notes(PyScene{scalecert::Scene::load(path_arg(path, "path"), numbers), nullptr, numbers});
            },
            py::arg("path"), py::arg("numbers") = "double",
            "a scene file (JSON); its objects given by vertices or as \"parts\" (each may have a \"name\"); "
            "JSON numbers and mesh decimals read as numbers says ('double', 'float32' or 'exact'; JSON strings are "
            "exact always); "
            "a note on reading (an OBJ mesh with several groups read as one convex object, decimals that are not "
            "doubles exactly) is a UserWarning")
        .def_static(
            "from_meshes",
            [](const py::handle& p1, const py::handle& p2, const py::handle& i1, const py::handle& i2,
               const py::handle& groups, const py::handle& numbers_, const py::handle& poses_,
               const py::handle& seeds_) {
                const scalecert::Numbers numbers = numbers_arg(numbers_);
                std::array<std::optional<scalecert::Pose>, 2> poses;
                if (!poses_.is_none()) {
                    const py::list l = as_list(poses_, "poses");
                    if (l.size() != 2)
                        throw scalecert::InputError("poses: expected (pose1, pose2); either may be None");
                    for (size_t i = 0; i < 2; ++i) {
                        if (l[i].is_none()) continue;
                        const std::string what = "poses[" + std::to_string(i) + "]";
                        const py::list rows = as_list(l[i], what);
                        if (rows.size() != 3) throw scalecert::InputError(what + ": expected 3 rows [r1, r2, r3, t]");
                        scalecert::Pose& m = poses[i].emplace();
                        for (size_t r = 0; r < 3; ++r) {
                            const std::string wr = what + "[" + std::to_string(r) + "]";
                            const py::list row = as_list(rows[r], wr);
                            if (row.size() != 4)
                                throw scalecert::InputError(wr + ": expected 4 numbers [r1, r2, r3, t]");
                            for (size_t k = 0; k < 4; ++k) m[r][k] = rational(row[k], wr.c_str(), numbers);
                        }
                    }
                }
                return warn_notes(PyScene{
                    scalecert::Scene::from_meshes(path_arg(p1, "p1"), path_arg(p2, "p2"), interval(i1, "I1", numbers),
                                                  interval(i2, "I2", numbers), flag_arg(groups, "parts_from_groups"),
                                                  numbers, poses, seeds_of(seeds_, numbers)),
                    nullptr, numbers});
            },
            py::arg("p1"), py::arg("p2"), py::arg("I1") = py::none(), py::arg("I2") = py::none(),
            py::arg("parts_from_groups") = false, py::arg("numbers") = "double", py::arg("poses") = py::none(),
            py::arg("seeds") = py::none(),
            "mesh files (.off .obj .ply .stl; text decimals and float I1, I2 read as numbers says), each one convex "
            "object; seeds = (seed1, seed2), each None (the mean of the object's points) or a point in its mesh's "
            "frame; poses = (pose1, pose2), each None or a 3x4 [R | t] by rows (e.g. a numpy array) moving that "
            "object's points and seed to R.v + t exactly before anything else; with parts_from_groups=True each OBJ "
            "file's "
            "groups with faces are its convex parts, named by their groups (other formats have no groups: each "
            "stays one convex object). An OBJ file with several groups read "
            "as one convex object gives a UserWarning saying so");
}

// What a Scene holds: its objects' parts and their names, the notes on reading it, its seeds and its
// file's text.
void bind_scene_contents(py::class_<PyScene>& scene) {
    scene
        .def_property_readonly(
            "convex", [](const PyScene& s) { return s.scene.convex(); },
            "True for two convex objects; False when an object is made of parts")
        .def(
            "part_count",
            [](const PyScene& s, const py::handle& i) { return s.scene.part_count(count_arg(i, "i", 0, 1)); },
            py::arg("i"), "the number of parts of object i (0: P1, 1: P2); 1 for a convex object")
        .def(
            "part_name",
            [](const PyScene& s, const py::handle& i, const py::handle& k) {
                const int obj = count_arg(i, "i", 0, 1);
                return s.scene.part_name(obj, static_cast<size_t>(count_arg(k, "k", 0, 2147483647L)));
            },
            py::arg("i"), py::arg("k"),
            "the name of part k of object i (a scene's part \"name\", an OBJ group's name); \"\" when it has none")
        .def(
            "notes", [](const PyScene& s) { return s.scene.notes(); },
            "remarks from reading the scene (an OBJ mesh with several groups read as one convex object): a list of "
            "str, empty when there are none")
        .def("seeds",
             [](const PyScene& s) { return py::make_tuple(fractions(s.scene.seed(0)), fractions(s.scene.seed(1))); })
        .def(
            "radii",
            [](const PyScene& s) { return py::make_tuple(fraction(s.scene.radius(0)), fraction(s.scene.radius(1))); },
            "the objects' radii as Fractions (0 for an object without one)")
        .def(
            "part_radii",
            [](const PyScene& s, int i) {
                if (i != 0 && i != 1) throw scalecert::InputError("part_radii: i is 0 (P1) or 1 (P2)");
                py::list out;
                for (size_t k = 0; k < s.scene.part_count(i); ++k) out.append(fraction(s.scene.part_radius(i, k)));
                return out;
            },
            py::arg("i"), "object i's parts' radii as Fractions (0 for a part without one)")
        .def(
            "json", [](const PyScene& s) { return s.scene.json(); }, "the scene file text, every number exact")
        .def(
            "curve", [](const PyScene& s) { return curve_dict(s.a().curve()); },
            "pieces (rho1 range, slope, intercept, normal, contact, features), switch points, growth distance");
}

// A Scene's exact answers: the curve, queries and verdicts, the region, plane checks and the partition.
void bind_scene_answers(py::class_<PyScene>& scene) {
    scene
        .def(
            "query",
            [](const PyScene& s, const py::handle& r1, const py::handle& r2) {
                const Rational a = rational(r1, "rho1", s.numbers), b = rational(r2, "rho2", s.numbers);
                const scalecert::QueryResult q = s.a().query(a, b);
                py::dict d;
                d["verdict"] = q.verdict;
                if (q.plane) {
                    py::dict p;
                    p["normal"] = fractions(q.plane->normal);
                    p["c1"] = fraction(q.plane->c1);
                    p["c2"] = fraction(q.plane->c2);
                    p["offset"] = fraction(q.plane->offset);
                    d["plane"] = p;
                } else {
                    d["plane"] = py::none();
                }
                if (q.common)
                    d["common_point"] =
                        py::dict(py::arg("rho1") = fraction(q.common->rho1), py::arg("rho2") = fraction(q.common->rho2),
                                 py::arg("point") = fractions(q.common->point));
                else
                    d["common_point"] = py::none();
                d["certificate"] = json_loads(s.a().query_json(a, b));
                return d;
            },
            py::arg("rho1"), py::arg("rho2"), "the exact verdict at (rho1, rho2) > 0, with its certificate")
        .def(
            "classify",
            [](const PyScene& s, const py::handle& r1, const py::handle& r2) {
                if (s.numbers == scalecert::Numbers::Exact)
                    throw scalecert::InputError(
                        "classify: takes the doubles (or, for a scene of numbers='float32', the floats) a program "
                        "held, not decimals as written (numbers='exact'): use verdict() per pair");
                const scalecert::Analysis& an = s.a();
                const bool single = s.numbers == scalecert::Numbers::Float32;
                return classify_array(r1, r2, [&an, single](std::vector<double> a, std::vector<double> b) {
                    // A float32 program held the float nearest each double (beyond its range: inf,
                    // refused as classify refuses any pair that is not two finite numbers > 0).
                    if (single)
                        for (auto* v : {&a, &b})
                            for (double& x : *v) x = static_cast<double>(static_cast<float>(x));
                    return an.classify(a, b, 0);
                });
            },
            py::arg("rho1"), py::arg("rho2"),
            "exact verdicts at the doubles' exact values (for a scene of numbers='float32', the floats nearest "
            "them), on all cores: an int8 array of Verdict values")
        .def(
            "verdict",
            [](const PyScene& s, const py::handle& r1, const py::handle& r2) {
                return s.a().verdict(rational(r1, "rho1", s.numbers), rational(r2, "rho2", s.numbers));
            },
            py::arg("rho1"), py::arg("rho2"), "the exact verdict at (rho1, rho2) > 0")
        .def(
            "region", [](const PyScene& s) { return json_loads(s.a().region_json()); },
            "what scalecert region writes, as a dict: pair polygons, their union, the labelled boundary, switch "
            "points, growth set")
        .def(
            "check_plane",
            [](const PyScene& s, const py::handle& r1, const py::handle& r2, const py::handle& n,
               const py::handle& offset) {
                std::optional<Rational> off;
                if (!offset.is_none()) off = rational(offset, "offset", s.numbers);
                const scalecert::PlaneCheck c =
                    s.a().check_plane(rational(r1, "rho1", s.numbers), rational(r2, "rho2", s.numbers),
                                      point(n, "normal", s.numbers), off);
                return py::dict(py::arg("separates") = c.separates, py::arg("c1") = fraction(c.c1),
                                py::arg("c2") = fraction(c.c2));
            },
            py::arg("rho1"), py::arg("rho2"), py::arg("normal"), py::arg("offset") = py::none(),
            "does the plane normal.x = offset (or some plane of that normal) separate P1(rho1) and P2(rho2)?")
        .def("curve_json", [](const PyScene& s) { return json_loads(s.a().curve_json()); })
        .def(
            "partition", [](const PyScene& s) { return json_loads(s.a().partition_json()); },
            "the certified partition of I1 x I2 (the certificate), as a dict")
        .def(
            "partition_json", [](const PyScene& s) { return s.a().partition_json(); },
            "the certificate as text, byte-identical to scalecert partition");
}

// A Scene's judging of claims: a claims file's (certify_fp) and arrays of one kind (certify).
void bind_scene_claims(py::class_<PyScene>& scene) {
    scene
        .def(
            "certify_fp",
            [](const PyScene& s, const py::handle& claims, const py::handle& exact_decimals,
               const py::handle& tolerance, const py::handle& certificate, const py::handle& abs_tolerance,
               const py::handle& numbers) -> py::object {
                scalecert::ClaimOptions opt;
                opt.numbers = numbers.is_none() ? s.numbers : numbers_arg(numbers);
                // exact_decimals=True: the earlier name of numbers='exact'.
                if (flag_arg(exact_decimals, "exact_decimals")) {
                    if (opt.numbers != scalecert::Numbers::Double && opt.numbers != scalecert::Numbers::Exact)
                        throw scalecert::InputError("exact_decimals=True and numbers='float32' disagree");
                    opt.numbers = scalecert::Numbers::Exact;
                }
                opt.tolerance = rational(tolerance, "tolerance");
                opt.abs_tolerance = rational(abs_tolerance, "abs_tolerance");
                opt.certificate = flag_arg(certificate, "certificate");
                scalecert::ClaimReport r = s.a().certify_fp(claims_text(claims), opt);
                if (!opt.certificate) return json_loads(r.report);
                return py::make_tuple(json_loads(r.report), r.certificate);
            },
            py::arg("claims"), py::arg("exact_decimals") = false, py::arg("tolerance") = 0,
            py::arg("certificate") = false, py::arg("abs_tolerance") = 0, py::arg("numbers") = py::none(),
            "marks claims right or wrong: the text of a claims file (JSON scalecert-claims-1, or 'RHO1 RHO2 VERDICT' / "
            "'curve RHO1 RHO2' / 'growth RHO' lines), a scalecert-claims-1 dict, or a list of claim dicts. A JSON "
            "number or decimal (a float: its shortest repr) is read as numbers says (default: as the scene's were): "
            "'double' (the double it is), "
            "'float32' (the float a float32 program holds) or 'exact' (as written; exact_decimals=True is the same); "
            "a str or a Fraction is exact. "
            "tolerance and abs_tolerance as certify-fp's --tolerance and --abs-tolerance. "
            "Returns the report of scalecert certify-fp --json, as a dict; with certificate=True, (the report, the "
            "judgements certificate's text for scalecert-check)")
        .def(
            "certify",
            [](const PyScene& s, const py::handle& kind, const py::handle& rho1, const py::handle& rho2,
               const py::handle& value, const py::handle& closest, const py::handle& direction,
               const py::handle& normal, const py::handle& offset, const py::handle& point_, const py::handle& verdict,
               const py::handle& tolerance, const py::handle& certificate, const py::handle& fractions,
               const py::handle& abs_tolerance, const py::handle& numbers, const py::handle& parts,
               const py::handle& pose1, const py::handle& pose2) {
                const scalecert::Analysis& a = s.a();
                return certify_arrays(
                    [&a](const auto& c, const auto& o) { return a.certify(c, o); }, text_arg(kind, "kind"), rho1, rho2,
                    value, closest, direction, normal, offset, point_, verdict, tolerance, abs_tolerance,
                    flag_arg(certificate, "certificate"), flag_arg(fractions, "fractions"),
                    numbers.is_none() ? s.numbers : numbers_arg(numbers), parts, pose1, pose2, !s.scene.convex());
            },
            py::arg("kind"), py::arg("rho1"), py::arg("rho2"), py::arg("value") = py::none(),
            py::arg("closest") = py::none(), py::arg("direction") = py::none(), py::arg("normal") = py::none(),
            py::arg("offset") = py::none(), py::arg("point") = py::none(), py::arg("verdict") = py::none(),
            py::arg("tolerance") = 0, py::arg("certificate") = false, py::arg("fractions") = false,
            py::arg("abs_tolerance") = 0, py::arg("numbers") = py::none(), py::arg("parts") = py::none(),
            py::arg("pose1") = py::none(), py::arg("pose2") = py::none(),
            "claims of one kind over arrays: kind 'distance' (value, optional closest of shape (n, 2, 3)), "
            "'penetration_depth' (value, optional direction (n, 3); on objects made of parts, parts (n, 2): the part "
            "pair "
            "of each contact); pose1, pose2 (n, 3, 4): each claim's objects at poses [R | t] by rows, as the scene "
            "places them; "
            "'verdict' (verdict: a str or n strs), "
            "'separating_plane' (normal (n, 3), optional offset) or 'witness_point' (point (n, 3)); rho1, rho2 and "
            "value "
            "of length n. A float is read as numbers says (default: as the scene's were; 'double': the double it is; "
            "'float32': the float nearest "
            "it; "
            "'exact': its shortest decimal). tolerance is a relative error, abs_tolerance a length within "
            "which points, distances, depths and planes may be off (certificates/CLAIMS.md, 'Tolerances'; give '1e-9' "
            "or a "
            "Fraction for the decimal). Returns a dict of numpy arrays: right (bool), value_right, "
            "closest_right, direction_right (bool, where given), exact (float64: the exact distance or depth, "
            "correctly "
            "rounded; NaN for a depth of a separated pair) and rel_error (float64), exact_verdict (verdicts); with "
            "fractions=True exact_squared (Fractions); with certificate=True the judgements certificate's text; on "
            "objects made of parts exact_parts (int64 (n, 2): the part pair each exact answer rests on, a verdict's "
            "meeting pair, a distance's closest pair, a depth's pair; -1 for none) and exact_part_names (their names, "
            "'' for a part without one)");
}

// Scene.audit: method(rho1, rho2) called once on the pairs (those given, or the golden data's), each
// answer judged as certify judges a verdict claim at the exact value of the doubles asked.
py::dict audit_method(const PyScene& s, const py::function& method, const py::handle& rho1, const py::handle& rho2,
                      const py::handle& listed) {
    const scalecert::Analysis& a = s.a();
    const int cap = count_arg(listed, "listed", 0, 1000000);
    if (rho1.is_none() != rho2.is_none()) throw scalecert::InputError("audit: give rho1 and rho2 together, or neither");
    // The pairs: those given, or the golden data's (its queries' doubles, each once).
    std::vector<double> r1, r2;
    if (rho1.is_none()) {
        const py::dict g = json_loads(a.golden().json);
        std::set<std::pair<double, double>> seen;
        for (const py::handle q : g["queries"].cast<py::list>()) {
            const double x = q["rho1_double"].cast<double>(), y = q["rho2_double"].cast<double>();
            if (seen.insert({x, y}).second) r1.push_back(x), r2.push_back(y);
        }
    } else {
        const DoubleArray a1 = doubles_of(rho1, "rho1", "audit"), a2 = doubles_of(rho2, "rho2", "audit");
        if (a1.ndim() != 1 || a2.ndim() != 1 || a1.size() != a2.size())
            throw scalecert::InputError("audit: rho1 and rho2 are one-dimensional arrays of one length");
        r1.assign(a1.data(), a1.data() + a1.size());
        r2.assign(a2.data(), a2.data() + a2.size());
        for (size_t i = 0; i < r1.size(); ++i)
            if (!(std::isfinite(r1[i]) && std::isfinite(r2[i]) && r1[i] > 0 && r2[i] > 0))
                throw scalecert::InputError("audit: pair " + std::to_string(i) + ": scalings are finite numbers > 0");
    }
    // A float32 program is asked the floats nearest them, and judged at those.
    if (s.numbers == scalecert::Numbers::Float32)
        for (auto* v : {&r1, &r2})
            for (double& x : *v) x = static_cast<double>(static_cast<float>(x));
    const size_t n = r1.size();
    py::array_t<double> A(static_cast<py::ssize_t>(n), r1.data()), B(static_cast<py::ssize_t>(n), r2.data());
    const py::object said = method(A, B);
    // The answers: one per pair; a word that is not a verdict, or no word, is no answer.
    const bool sequence = py::isinstance<py::sequence>(said) && !py::isinstance<py::str>(said) &&
                          py::hasattr(said, "__len__");  // (not a dict, a set, a string)
    if (!sequence || py::len(said) != n)
        throw scalecert::InputError("audit: the method returned " +
                                    (sequence ? std::to_string(py::len(said)) + " answers" : "no sequence") + " for " +
                                    std::to_string(n) + " pairs");
    std::vector<std::string> words(n);
    std::vector<std::optional<scalecert::ClaimedVerdict>> verdict(n);
    const py::sequence seq = said.cast<py::sequence>();
    for (size_t i = 0; i < n; ++i) {
        const py::object w = seq[i];
        if (py::isinstance<py::str>(w)) {
            try {
                words[i] = w.cast<std::string>();
            } catch (const py::cast_error&) {  // not UTF-8 (a lone surrogate): no verdict word
                words[i].clear();
            }
        }
        verdict[i] = claimed_verdict(words[i]);
        if (!verdict[i]) words[i] = py::repr(w).cast<std::string>().substr(0, 60);
    }
    // Judged a block at a time: a judgement holds its exact values, and a million of
    // them at once would hold gigabytes.
    std::vector<char> judged_right(n, 0);
    constexpr size_t kBlock = 65536;
    for (size_t b = 0; b < n; b += kBlock) {
        std::vector<scalecert::Claim> claims;
        std::vector<size_t> at;
        for (size_t i = b; i < std::min(n, b + kBlock); ++i)
            if (verdict[i]) {
                scalecert::Claim c;
                c.kind = scalecert::ClaimKind::Verdict;
                c.rho1 = scalecert::exact(r1[i]);
                c.rho2 = scalecert::exact(r2[i]);
                c.verdict = *verdict[i];
                claims.push_back(std::move(c));
                at.push_back(i);
            }
        const scalecert::Judgements j = a.certify(claims);
        for (size_t k = 0; k < at.size(); ++k) judged_right[at[k]] = j.items[k].right;
    }
    const std::vector<scalecert::Verdict> exact = a.classify(r1, r2, 0);
    py::array_t<bool> right(static_cast<py::ssize_t>(n));
    auto rw = right.mutable_unchecked<1>();
    py::list failures, exact_names;
    long wrong = 0, false_sep = 0, false_int = 0, false_touch = 0, no_answer = 0;
    for (size_t i = 0; i < n; ++i) {
        const bool answered = verdict[i].has_value();
        const bool ok = answered && judged_right[i];
        rw(static_cast<py::ssize_t>(i)) = ok;
        exact_names.append(scalecert::name(exact[i]));
        if (ok) continue;
        ++wrong;
        ++(!answered                                             ? no_answer
           : *verdict[i] == scalecert::ClaimedVerdict::Separated ? false_sep
           : *verdict[i] == scalecert::ClaimedVerdict::Touching  ? false_touch
                                                                 : false_int);
        if (failures.size() < static_cast<size_t>(cap))
            failures.append(py::dict(py::arg("rho1") = r1[i], py::arg("rho2") = r2[i],
                                     py::arg("said") = answered ? words[i] : "no answer: " + words[i],
                                     py::arg("exact") = scalecert::name(exact[i])));
    }
    return py::dict(py::arg("queries") = n, py::arg("wrong") = wrong, py::arg("false_separated") = false_sep,
                    py::arg("false_overlapping") = false_int, py::arg("false_touching") = false_touch,
                    py::arg("no_answer") = no_answer, py::arg("right") = right, py::arg("exact_verdict") = exact_names,
                    py::arg("failures") = failures);
}

// A Scene's golden data, and the audit of the user's own collision test.
void bind_scene_golden_and_audit(py::class_<PyScene>& scene) {
    scene
        .def(
            "golden",
            [](const PyScene& s, const py::handle& verticals, const py::handle& offsets) {
                const scalecert::GoldenOptions o = golden_options(verticals, offsets);
                scalecert::GoldenData g = s.a().golden(o);
                return py::make_tuple(json_loads(g.json), g.csv, g.rational_csv);
            },
            py::arg("verticals") = 7, py::arg("offsets") = py::none(),
            "the scene's golden data: (the golden JSON as a dict, the decimal CSV text, the rational CSV text), "
            "as scalecert golden writes per scene; verticals and offsets (a list of K: pairs 2^-K away; default "
            "[4, 12, 20, 30, 40, 52]) as its --verticals and --offsets")
        .def("audit", &audit_method, py::arg("method"), py::arg("rho1") = py::none(), py::arg("rho2") = py::none(),
             py::arg("listed") = 50,
             "audits your own collision test: method(rho1, rho2) is called once with two float64 arrays of "
             "scalings (default: the golden data's pairs, near every piece of the boundary in I1 x I2; a scene "
             "of numbers='float32' is asked the floats nearest them) and returns one verdict word per pair "
             "('separated', 'touching', 'overlapping' or 'intersecting'), each judged as certify judges a verdict "
             "claim at the exact value of the numbers asked; anything else (None, NaN, another word) is no answer, "
             "judged wrong. Returns a dict: queries, wrong (the sum of the next four), false_separated (said "
             "separated where they meet), false_overlapping (said overlapping or intersecting, wrongly), "
             "false_touching (said touching where they do not touch), no_answer, right (bool array), "
             "exact_verdict, and failures: the first `listed` wrong pairs (rho1, rho2, said, exact)");
}

// The class Scene: a scene with its analysis, built on first use.
void bind_scene(py::module_& m) {
    py::class_<PyScene> scene(m, "Scene");
    bind_scene_construction(scene);
    bind_scene_contents(scene);
    bind_scene_answers(scene);
    bind_scene_claims(scene);
    bind_scene_golden_and_audit(scene);
}

// The module's function golden: a family's scenes with their exact answers, into a folder.
void bind_golden(py::module_& m) {
    m.def(
        "golden",
        [](const py::handle& family, const py::handle& count, const py::handle& seed, const py::handle& eps,
           const py::handle& dir, const py::handle& verticals, const py::handle& offsets) {
            const std::string f = text_arg(family, "family");
            const int n = count_arg(count, "count", 1, 10000000);
            const unsigned long long sd = seed_arg(seed, "seed");
            const Rational e = rational(eps, "eps");
            if (sgn(e) <= 0) throw scalecert::InputError("eps must be > 0");
            const scalecert::GoldenOptions o = golden_options(verticals, offsets);
            scalecert::write_golden(f, n, sd, e, path_arg(dir, "dir"), o);
        },
        py::arg("family"), py::arg("count"), py::arg("seed"), py::arg("eps"), py::arg("dir"), py::arg("verticals") = 7,
        py::arg("offsets") = py::none(),
        "writes COUNT scenes of FAMILY with exact answers into DIR, as scalecert golden does");
}

// judge_mujoco's arguments: qpos None, or rows of nq floats (a 2-D numpy array or lists); key None
// or an int >= 0.
scalecert::MujocoJudgement mujoco_judgement(const py::handle& model, const py::handle& qpos, const py::handle& key,
                                            const py::handle& tolerance, const py::handle& abs_tolerance,
                                            const py::handle& failures, bool intended = false) {
    scalecert::MujocoOptions o;
    o.intended = intended;
    o.tolerance = rational(tolerance, "tolerance");
    o.abs_tolerance = rational(abs_tolerance, "abs_tolerance");
    if (!key.is_none()) o.key = count_arg(key, "key", 0, 1 << 30);
    if (!failures.is_none()) {
        o.failures = path_arg(failures, "failures");
        if (o.failures.empty()) throw scalecert::InputError("failures: an empty path (give None for no reproducers)");
    }
    std::vector<std::vector<double>> states;
    if (!qpos.is_none()) {
        // Rows of real numbers (ints, floats, numpy's), each the double a program holds: no bool,
        // bytes, complex, or number beyond the doubles.
        const py::object real = py::module_::import("numbers").attr("Real");
        try {
            const py::list rows = as_list(qpos, "qpos");
            for (size_t i = 0; i < rows.size(); ++i) {
                const std::string what = "qpos[" + std::to_string(i) + "]";
                if (py::isinstance<py::bytes>(rows[i]) || py::isinstance<py::bytearray>(rows[i]))
                    throw scalecert::InputError(what + ": expected a row of numbers, not bytes");
                const py::list row = as_list(rows[i], what);
                std::vector<double> q;
                for (const py::handle x : row) {
                    if (py::isinstance<py::bool_>(x) || !py::isinstance(x, real))
                        throw scalecert::InputError(what + ": expected real numbers");
                    const double d = py::float_(py::reinterpret_borrow<py::object>(x)).cast<double>();
                    if (!std::isfinite(d)) throw scalecert::InputError(what + ": a qpos of finite numbers only");
                    q.push_back(d);
                }
                states.push_back(std::move(q));
            }
        } catch (const py::error_already_set& e) {
            if (!argument_error(e)) throw;
            throw scalecert::InputError("qpos: not rows of numbers a double holds (" + std::string(e.what()) + ")");
        }
        if (states.empty()) throw scalecert::InputError("qpos: no state (give None for qpos0)");
    }
    return scalecert::judge_mujoco(path_arg(model, "model"), states, o);
}

// MuJoCo's own arrays, read by their attribute names (MjModel, MjData, their contacts): numbers
// flattened, each checked to be what MuJoCo's field holds (an int, a float32, a finite double).
std::vector<double> held_numbers(const py::handle& owner, const char* owner_name, const char* name) {
    const std::string what = std::string(owner_name) + "." + name;
    if (!py::hasattr(owner, name)) throw scalecert::InputError(what + ": missing (MuJoCo's field of that name)");
    try {
        const py::object np = py::module_::import("numpy");
        const py::array a = np.attr("asarray")(owner.attr(name));
        const std::string kind = py::str(a.dtype().attr("kind"));
        if (kind != "i" && kind != "u" && kind != "f")
            throw scalecert::InputError(what + ": expected numbers (dtype " + std::string(py::str(a.dtype())) + ")");
        const py::array_t<double, py::array::c_style | py::array::forcecast> d = np.attr("ravel")(a);
        return std::vector<double>(d.data(), d.data() + d.size());
    } catch (const py::error_already_set& e) {
        if (!argument_error(e)) throw;
        throw scalecert::InputError(what + ": not an array of numbers (" + std::string(e.what()) + ")");
    }
}
std::vector<int> held_ints(const py::handle& owner, const char* owner_name, const char* name) {
    std::vector<int> out;
    for (double x : held_numbers(owner, owner_name, name)) {
        if (!(x == std::floor(x) && std::fabs(x) < 2147483648.0))
            throw scalecert::InputError(std::string(owner_name) + "." + name + ": expected integers");
        out.push_back(static_cast<int>(x));
    }
    return out;
}
int held_int(const py::handle& owner, const char* owner_name, const char* name) {
    const std::vector<int> v = held_ints(owner, owner_name, name);
    if (v.size() != 1) throw scalecert::InputError(std::string(owner_name) + "." + name + ": expected one integer");
    return v[0];
}
std::vector<double> held_doubles(const py::handle& owner, const char* owner_name, const char* name) {
    std::vector<double> v = held_numbers(owner, owner_name, name);
    for (double x : v)
        if (!std::isfinite(x))
            throw scalecert::InputError(std::string(owner_name) + "." + name + ": a NaN or an infinity");
    return v;
}
// Names from MjModel.names and name_geomadr / name_bodyadr, where the model has them ("" else).
std::vector<std::string> held_names(const py::handle& m, const char* adr, size_t n) {
    std::vector<std::string> out(n);
    if (!py::hasattr(m, "names") || !py::hasattr(m, adr)) return out;
    const py::object names = m.attr("names");
    if (!py::isinstance<py::bytes>(names)) return out;
    const std::string all = names.cast<std::string>();
    const std::vector<int> at = held_ints(m, "model", adr);
    for (size_t i = 0; i < n && i < at.size(); ++i)
        if (at[i] >= 0 && static_cast<size_t>(at[i]) < all.size()) out[i] = all.c_str() + at[i];
    return out;
}
scalecert::MujocoHeldModel held_model(const py::handle& m) {
    scalecert::MujocoHeldModel h;
    const char* M = "model";
    h.nq = held_int(m, M, "nq");
    h.geom_type = held_ints(m, M, "geom_type");
    h.geom_bodyid = held_ints(m, M, "geom_bodyid");
    h.geom_contype = held_ints(m, M, "geom_contype");
    h.geom_conaffinity = held_ints(m, M, "geom_conaffinity");
    h.geom_dataid = held_ints(m, M, "geom_dataid");
    h.geom_size = held_doubles(m, M, "geom_size");
    h.geom_margin = held_doubles(m, M, "geom_margin");
    h.geom_gap = held_doubles(m, M, "geom_gap");
    h.body_parentid = held_ints(m, M, "body_parentid");
    h.body_weldid = held_ints(m, M, "body_weldid");
    h.geom_names = held_names(m, "name_geomadr", h.geom_type.size());
    h.body_names = held_names(m, "name_bodyadr", h.body_parentid.size());
    h.mesh_vertadr = held_ints(m, M, "mesh_vertadr");
    h.mesh_vertnum = held_ints(m, M, "mesh_vertnum");
    for (double x : held_doubles(m, M, "mesh_vert")) {
        if (static_cast<double>(static_cast<float>(x)) != x) {
            char shown[40];
            std::snprintf(shown, sizeof shown, "%.17g", x);
            throw scalecert::InputError(std::string("model.mesh_vert: ") + shown +
                                        " is not a float32 (MuJoCo holds mesh vertices as float32)");
        }
        h.mesh_vert.push_back(static_cast<float>(x));
    }
    h.pair_geom1 = held_ints(m, M, "pair_geom1");
    h.pair_geom2 = held_ints(m, M, "pair_geom2");
    h.pair_margin = held_doubles(m, M, "pair_margin");
    h.pair_gap = held_doubles(m, M, "pair_gap");
    h.exclude_signature = held_ints(m, M, "exclude_signature");
    if (!py::hasattr(m, "opt")) throw scalecert::InputError("model.opt: missing (MuJoCo's field of that name)");
    const py::object opt = m.attr("opt");
    h.opt_disableflags = held_int(opt, "model.opt", "disableflags");
    h.opt_enableflags = held_int(opt, "model.opt", "enableflags");
    h.opt_collision = held_int(opt, "model.opt", "collision");
    const std::vector<double> om = held_doubles(opt, "model.opt", "o_margin");
    if (om.size() != 1) throw scalecert::InputError("model.opt.o_margin: expected one number");
    h.opt_o_margin = om[0];
    return h;
}
scalecert::MujocoHeldData held_data(const py::handle& d, const std::string& where, long nconmax) {
    scalecert::MujocoHeldData h;
    const std::string D = where;
    h.qpos = held_doubles(d, D.c_str(), "qpos");
    h.geom_xpos = held_numbers(d, D.c_str(), "geom_xpos");
    h.geom_xmat = held_numbers(d, D.c_str(), "geom_xmat");
    if (!py::hasattr(d, "contact")) throw scalecert::InputError(D + ".contact: missing (MuJoCo's field of that name)");
    const py::object c = d.attr("contact");
    const std::string C = D + ".contact";
    const std::vector<int> g1 = held_ints(c, C.c_str(), "geom1"), g2 = held_ints(c, C.c_str(), "geom2"),
                           ex = held_ints(c, C.c_str(), "exclude");
    const std::vector<double> dist = held_numbers(c, C.c_str(), "dist"), pos = held_numbers(c, C.c_str(), "pos"),
                              frame = held_numbers(c, C.c_str(), "frame"),
                              inc = held_numbers(c, C.c_str(), "includemargin");
    size_t n = g1.size();
    if (py::hasattr(d, "ncon")) {
        const int ncon = held_int(d, D.c_str(), "ncon");
        if (ncon < 0 || static_cast<size_t>(ncon) > n)
            throw scalecert::InputError(D + ".ncon: " + std::to_string(ncon) + " contacts, " + C + " holds " +
                                        std::to_string(n));
        n = static_cast<size_t>(ncon);
    }
    if (g2.size() < n || ex.size() < n || dist.size() < n || inc.size() < n || pos.size() < 3 * n ||
        frame.size() < 9 * n)
        throw scalecert::InputError(C + ": its fields hold different numbers of contacts");
    for (size_t i = 0; i < n; ++i) {
        scalecert::MujocoHeldContact k;
        k.geom1 = g1[i];
        k.geom2 = g2[i];
        k.dist = dist[i];
        for (size_t j = 0; j < 3; ++j) k.pos[j] = pos[3 * i + j];
        for (size_t j = 0; j < 9; ++j) k.frame[j] = frame[9 * i + j];
        k.includemargin = inc[i];
        k.exclude = ex[i];
        h.contact.push_back(k);
    }
    h.contact_buffer_full = nconmax > 0 && static_cast<long>(n) >= nconmax;
    return h;
}
// judge_mujoco_held's arguments: data one MjData-like object or a list of them.
scalecert::MujocoJudgement mujoco_held_judgement(const py::handle& model, const py::handle& data,
                                                 const py::handle& tolerance, const py::handle& abs_tolerance,
                                                 const py::handle& failures) {
    scalecert::MujocoOptions o;
    o.tolerance = rational(tolerance, "tolerance");
    o.abs_tolerance = rational(abs_tolerance, "abs_tolerance");
    if (!failures.is_none()) {
        o.failures = path_arg(failures, "failures");
        if (o.failures.empty()) throw scalecert::InputError("failures: an empty path (give None for no reproducers)");
    }
    // MuJoCo's contact buffer (model.nconmax, where the model has it): a state that filled it
    // dropped contacts.
    const long nconmax = py::hasattr(model, "nconmax") ? held_int(model, "model", "nconmax") : 0;
    std::vector<scalecert::MujocoHeldData> states;
    if (py::isinstance<py::list>(data) || py::isinstance<py::tuple>(data)) {
        size_t i = 0;
        for (const py::handle d : data) states.push_back(held_data(d, "data[" + std::to_string(i++) + "]", nconmax));
    } else if (py::hasattr(data, "qpos")) {
        states.push_back(held_data(data, "data", nconmax));
    } else {
        throw scalecert::InputError("data: an MjData (or an object with its attributes), or a list or tuple of them");
    }
    return scalecert::judge_mujoco_held(held_model(model), states, o);
}

// scalecert.judge_mujoco, and the test helpers of scalecert.testing: assertions whose failure lists
// each wrong judgement (and where its reproducer is).
void bind_mujoco_and_testing(py::module_& m) {
    m.def(
        "judge_mujoco",
        [](const py::handle& model, const py::handle& qpos, const py::handle& key, const py::handle& tolerance,
           const py::handle& abs_tolerance, const py::handle& failures, bool intended) {
            return json_loads(mujoco_judgement(model, qpos, key, tolerance, abs_tolerance, failures, intended).json);
        },
        py::arg("model"), py::arg("qpos") = py::none(), py::arg("key") = py::none(), py::arg("tolerance") = 0,
        py::arg("abs_tolerance") = 0, py::arg("failures") = py::none(), py::arg("intended") = false,
        "scalecert mujoco: the model run by MuJoCo (Debian's libmujoco) at each qpos (rows of nq floats; None: "
        "keyframe `key`, else qpos0), every geom pair its pipeline considers judged exactly (with intended=True also "
        "against the model as written, each pair's 'intended'); the report as a dict "
        "(format scalecert-mujoco-1; summary['wrong_pairs'] counts the wrong pair states)");
    m.def(
        "judge_mujoco_held",
        [](const py::handle& model, const py::handle& data, const py::handle& tolerance,
           const py::handle& abs_tolerance, const py::handle& failures) {
            return json_loads(mujoco_held_judgement(model, data, tolerance, abs_tolerance, failures).json);
        },
        py::arg("model"), py::arg("data"), py::arg("tolerance") = 0, py::arg("abs_tolerance") = 0,
        py::arg("failures") = py::none(),
        "judge_mujoco on what the program's own MuJoCo holds: `model` an MjModel (or any object with its "
        "attributes: geom_type, geom_size, mesh_vert, body_parentid, pair_geom1, opt, ...), `data` an MjData after "
        "mj_forward or mj_step (qpos, geom_xpos, geom_xmat, contact, ncon), or a list of them, one a state");
    py::module_ t =
        m.def_submodule("testing", "assertions for pytest: each raises AssertionError listing every wrong judgement");
    // A MuJoCo gate's verdict: nothing judged fails, a wrong pair state fails listing each.
    auto gate = [](const scalecert::MujocoJudgement& j, const py::handle& failures) {
        if (j.judgements == 0) {  // a gate that checked nothing fails
            PyErr_SetString(PyExc_AssertionError, ("scalecert: nothing of the model was judged:\n" + j.text).c_str());
            throw py::error_already_set();
        }
        if (j.wrong_pairs == 0) return;
        std::string msg = "scalecert: MuJoCo was wrong at " + std::to_string(j.wrong_pairs) + " pair state" +
                          (j.wrong_pairs == 1 ? "" : "s") + ":\n" + j.text;
        if (!failures.is_none())
            msg += "reproducers (scalecert certify-fp replays them): " + path_arg(failures, "failures");
        PyErr_SetString(PyExc_AssertionError, msg.c_str());
        throw py::error_already_set();
    };
    t.def(
        "assert_mujoco",
        [gate](const py::handle& model, const py::handle& qpos, const py::handle& key, const py::handle& tolerance,
               const py::handle& abs_tolerance, const py::handle& failures) {
            gate(mujoco_judgement(model, qpos, key, tolerance, abs_tolerance, failures), failures);
        },
        py::arg("model"), py::arg("qpos") = py::none(), py::arg("key") = py::none(), py::arg("tolerance") = 0,
        py::arg("abs_tolerance") = 0, py::arg("failures") = py::none(),
        "judge_mujoco, raising AssertionError with each wrong judgement when any is wrong");
    t.def(
        "assert_mujoco_held",
        [gate](const py::handle& model, const py::handle& data, const py::handle& tolerance,
               const py::handle& abs_tolerance, const py::handle& failures) {
            gate(mujoco_held_judgement(model, data, tolerance, abs_tolerance, failures), failures);
        },
        py::arg("model"), py::arg("data"), py::arg("tolerance") = 0, py::arg("abs_tolerance") = 0,
        py::arg("failures") = py::none(),
        "judge_mujoco_held (the program's own MjModel and MjData), raising AssertionError with each wrong judgement "
        "when any is wrong");
    t.def(
        "assert_claims",
        [](const py::handle& scene, const py::handle& claims, const py::handle& tolerance,
           const py::handle& abs_tolerance, const py::handle& numbers) {
            if (!py::isinstance<PyScene>(scene)) throw scalecert::InputError("scene: expected a scalecert.Scene");
            const PyScene& s = scene.cast<const PyScene&>();
            scalecert::ClaimOptions opt;
            opt.numbers = numbers.is_none() ? s.numbers : numbers_arg(numbers);
            opt.tolerance = rational(tolerance, "tolerance");
            opt.abs_tolerance = rational(abs_tolerance, "abs_tolerance");
            opt.json = false;
            const scalecert::ClaimReport r = s.a().certify_fp(claims_text(claims), opt);
            if (r.claims == 0) {  // a gate that checked nothing fails
                PyErr_SetString(PyExc_AssertionError, "scalecert: no claims to judge");
                throw py::error_already_set();
            }
            if (r.wrong == 0) return;
            std::string msg =
                "scalecert: " + std::to_string(r.wrong) + " of " + std::to_string(r.claims) + " claims wrong:\n";
            for (size_t b = 0; b < r.report.size();) {
                const size_t e = r.report.find('\n', b);
                const std::string line = r.report.substr(b, e == std::string::npos ? std::string::npos : e - b);
                if (line.rfind("WRONG", 0) == 0) msg += line + "\n";
                if (e == std::string::npos) break;
                b = e + 1;
            }
            PyErr_SetString(PyExc_AssertionError, msg.c_str());
            throw py::error_already_set();
        },
        py::arg("scene"), py::arg("claims"), py::arg("tolerance") = 0, py::arg("abs_tolerance") = 0,
        py::arg("numbers") = py::none(),
        "Scene.certify_fp's claims (a claims file's text, a dict or a list of claim dicts), raising AssertionError "
        "with each wrong claim's line when any is wrong");
    // `import scalecert.testing` finds it too.
    py::module_::import("sys").attr("modules")["scalecert.testing"] = t;
}

}  // namespace

PYBIND11_MODULE(scalecert, m) {
    m.doc() = "Exact, certified collision of uniformly scaled convex polyhedra and of objects made of convex parts.";
    m.attr("__version__") = scalecert::version();
    py::register_exception<scalecert::InputError>(m, "InputError", PyExc_ValueError);

    bind_verdict(m);
    bind_scene(m);
    bind_golden(m);
    bind_mujoco_and_testing(m);
}
