// Loads two meshes, prints the exact touching curve, runs a query, and writes the certified
// partition of I1 x I2 (check it with scalecert-check).
//   certify_meshes P1_MESH P2_MESH CERTIFICATE_OUT
#include <scalecert/scalecert.hpp>

#include <fstream>
#include <iostream>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: certify_meshes P1_MESH P2_MESH CERTIFICATE_OUT\n";
        return 2;
    }
    try {
        using scalecert::Rational;
        const scalecert::Interval i1{Rational(1, 2), Rational(2)}, i2{Rational(1), Rational(4)};
        const scalecert::Scene scene = scalecert::Scene::from_meshes(argv[1], argv[2], i1, i2);
        const scalecert::Analysis a(scene);
        for (const scalecert::Piece& p : a.curve().pieces)
            std::cout << "piece rho1 in [" << p.from << ", " << p.to << "]: rho2 = " << p.slope << " rho1 + "
                      << p.intercept << "  (" << (p.contact ? scalecert::name(p.contact->kind) : "-") << ")\n";
        for (const scalecert::SwitchPoint& s : a.curve().switches)
            std::cout << "switch (" << s.rho1 << ", " << s.rho2 << ") "
                      << (s.contact ? scalecert::name(s.contact->kind) : "-") << "\n";
        std::cout << "growth distance " << a.curve().growth.value << "\n";
        const scalecert::QueryResult q = a.query(Rational(1), Rational(1));
        std::cout << "query (1, 1): " << scalecert::name(q.verdict) << "\n";
        std::ofstream(argv[3]) << a.partition_json();
        return 0;
    } catch (const scalecert::InputError& e) {
        std::cerr << "certify_meshes: " << e.what() << "\n";
        return 2;
    }
}
