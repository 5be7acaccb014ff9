// Bullet as it runs, judged: two box hulls (collision margin 0) at 1,000 random poses,
// btGjkEpaSolver2::Distance on each, every result turned into claims by scalecert/bullet.hpp and
// judged exactly. Prints the wrong results and the worst relative error; exits 1 if any was wrong
// beyond the tolerance.
//   bullet_boxes [TOLERANCE [ABS_TOLERANCE]]   (relative, and a length; both default 1e-5)
#include <scalecert/bullet.hpp>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

int main(int argc, char** argv) {
    const char* tol = argc > 1 ? argv[1] : "1e-5";
    const char* abs = argc > 2 ? argv[2] : "1e-5";
    btConvexHullShape h1, h2;
    for (int k = 0; k < 8; ++k) {
        h1.addPoint(btVector3(k & 1 ? 0.5f : -0.5f, k & 2 ? 1 : -1, k & 4 ? 1.5f : -1.5f));
        h2.addPoint(btVector3(k & 1 ? 0.25f : -0.25f, k & 2 ? 0.25f : -0.25f, k & 4 ? 2 : -2));
    }
    h1.setMargin(0);
    h2.setMargin(0);
    const scalecert::Analysis scene(scalecert::bullet_scene(h1, h2));
    std::mt19937_64 g(1);
    std::uniform_real_distribution<float> u(-1, 1);
    std::vector<scalecert::Claim> claims;
    std::vector<double> said;
    for (int i = 0; i < 1000; ++i) {
        btTransform a, b;
        a.setIdentity();
        b.setIdentity();
        b.setRotation(btQuaternion(u(g), u(g), u(g), u(g)).normalized());
        b.setOrigin(btVector3(4 * u(g), 4 * u(g), 4 * u(g)));
        btGjkEpaSolver2::sResults r;
        btGjkEpaSolver2::Distance(&h1, a, &h2, b, btVector3(1, 0, 0), r);
        for (const scalecert::Claim& c : scalecert::bullet_distance_claims(r, a, b)) claims.push_back(c);
        said.push_back(r.distance);
    }
    scalecert::ClaimOptions o;
    o.tolerance = scalecert::parse_rational(tol);
    o.abs_tolerance = scalecert::parse_rational(abs);
    const scalecert::Judgements j = scene.certify(claims, o);
    double worst = 0;
    long distances = 0;
    for (size_t i = 0; i < j.items.size(); ++i) {
        const scalecert::Judgement& k = j.items[i];
        const bool distance = claims[i].kind == scalecert::ClaimKind::Distance;
        if (distance) distances++, worst = std::max(worst, k.rel_error);
        if (!k.right)
            std::printf("pose %zu: Bullet said %.9g, exact %.17g (%s)\n", i, said[i], k.exact,
                        distance ? (*k.value_right ? "the closest points" : "distance") : "verdict");
    }
    std::printf(
        "%zu results (%ld distances, %ld collisions), %ld wrong at tolerance %s, abs %s; worst relative "
        "distance error %.3g\n",
        j.items.size(), distances, static_cast<long>(j.items.size()) - distances, j.wrong, tol, abs, worst);
    return j.wrong ? 1 : 0;
}
