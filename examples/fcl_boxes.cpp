// FCL as it runs, judged: two boxes at 1,000 random poses, fcl::distance on each, every result
// turned into claims by scalecert/fcl.hpp and judged exactly. Prints the wrong results and the
// worst relative error; exits 1 if any was wrong beyond the tolerance.
//   fcl_boxes [TOLERANCE]   (relative; default 1e-6)
#include <scalecert/fcl.hpp>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

int main(int argc, char** argv) {
    const scalecert::Rational tol = scalecert::parse_rational(argc > 1 ? argv[1] : "1e-6");
    auto b1 = std::make_shared<fcl::Boxd>(1, 2, 3), b2 = std::make_shared<fcl::Boxd>(0.5, 0.5, 4);
    const scalecert::Analysis scene(scalecert::fcl_scene<double>(*b1, *b2));
    std::mt19937_64 g(1);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<scalecert::Claim> claims;
    std::vector<double> said;
    for (int i = 0; i < 1000; ++i) {
        fcl::Transform3d t1 = fcl::Transform3d::Identity(), t2 = fcl::Transform3d::Identity();
        t2.linear() = fcl::Quaterniond(u(g), u(g), u(g), u(g)).normalized().toRotationMatrix();
        t2.translation() << 4 * u(g), 4 * u(g), 4 * u(g);
        fcl::CollisionObjectd o1(b1, t1), o2(b2, t2);
        fcl::DistanceRequestd request;
        fcl::DistanceResultd result;
        fcl::distance(&o1, &o2, request, result);
        for (const scalecert::Claim& c : scalecert::fcl_claims(request, result, t1, t2)) claims.push_back(c);
        said.push_back(result.min_distance);
    }
    scalecert::ClaimOptions o;
    o.tolerance = tol;
    const scalecert::Judgements j = scene.certify(claims, o);
    double worst = 0;
    long distances = 0;
    for (size_t i = 0; i < j.items.size(); ++i) {
        const scalecert::Judgement& k = j.items[i];
        if (claims[i].kind == scalecert::ClaimKind::Distance) distances++, worst = std::max(worst, k.rel_error);
        if (!k.right)
            std::printf("pose %zu: FCL said %.17g, exact %.17g (%s)\n", i, said[i], k.exact,
                        claims[i].kind == scalecert::ClaimKind::Distance ? "distance" : "verdict");
    }
    std::printf(
        "%zu results (%ld distances, %ld collisions), %ld wrong at relative tolerance %s; worst relative "
        "distance error %.3g\n",
        j.items.size(), distances, static_cast<long>(j.items.size()) - distances, j.wrong, argc > 1 ? argv[1] : "1e-6",
        worst);
    return j.wrong ? 1 : 0;
}
