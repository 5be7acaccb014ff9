// The touching curve of a certificate (checker/curve.*): contact labels at switch points and along
// pieces recomputed from all maximisers, pieces proved down to rho2 = 0, the curve's ends anchored by
// witnesses, and below rho2 = 0 one line. Forgeries, each written by hand.
#include "checker_tests.hpp"

BOOST_AUTO_TEST_SUITE(checker_curve)

BOOST_AUTO_TEST_CASE(switch_contact_labels_are_recomputed_from_all_maximisers) {
    // tetra_box_switch: P1's vertex 0 touches the middle of P2's edge {5, 7} at (1, 2), a (V,E)
    // contact (derived by hand in test_hand_curves). Listing one end of the edge does not make
    // it (V,V); listing a vertex that is not on the contact is refused; the true label passes.
    OJ j = bundled("tetra_box_switch");
    OJ& sp = j["switch_points"][0];
    BOOST_TEST_REQUIRE(sp["contact"] == "VE");
    OJ vv = j;
    vv["switch_points"][0]["contact"] = "VV";
    vv["switch_points"][0]["features"]["P2"] = OJ::array({5});
    BOOST_TEST(verdict_of(vv) == 1);
    OJ sub = j;
    sub["switch_points"][0]["features"]["P2"] = OJ::array({5});  // a subset with the true label: still true
    BOOST_TEST(verdict_of(sub) == 0);
    OJ off = j;
    off["switch_points"][0]["features"]["P2"] = OJ::array({4});  // on the (V,F) face, not on the contact
    BOOST_TEST(verdict_of(off) == 1);
    OJ ee = j;
    ee["switch_points"][0]["contact"] = "EE";
    ee["switch_points"][0]["features"]["P1"] = OJ::array({0, 1});
    BOOST_TEST(verdict_of(ee) == 1);
}

BOOST_AUTO_TEST_CASE(piece_contacts_where_normals_share_a_line_are_proved_minimal) {
    // Cubes [0,2]^3 and [2,4]×[2,4]×[0,2] (tests/data/cubes_sharing_an_edge.json) touch along the
    // edge {x = y = 2} on the line ρ2 = 2 − ρ1, given by the normals (1,0,0) and (0,1,0) alike:
    // each plane alone supports a face (FF), the contact is EE (derived in test_hand_curves).
    OJ j = fresh_partition("cubes_sharing_an_edge.json");
    OJ& p = j["pieces"][0];
    BOOST_TEST_REQUIRE(p["contact"] == "EE");
    BOOST_TEST_REQUIRE(p["same_line_normals"].size() == 1u);
    // The old label, one normal's faces, with that normal's maximisers and no other normal: no
    // witness can lie inside both faces, so the file's own witness (on the edge) is refused.
    OJ ff = j;
    const OJ face1 = OJ::array({4, 5, 6, 7}), face2 = OJ::array({0, 1, 2, 3});
    const bool x_first = p["normal"] == OJ::array({"1", "0", "0"});
    ff["pieces"][0]["contact"] = "FF";
    ff["pieces"][0]["features"]["P1"] = x_first ? face1 : OJ::array({2, 3, 6, 7});
    ff["pieces"][0]["features"]["P2"] = x_first ? face2 : OJ::array({0, 1, 4, 5});
    ff["pieces"][0].erase("same_line_normals");
    BOOST_TEST(verdict_of(ff) == 1);
    // Leaving the other normal out alone, or keeping it and claiming FF, or listing part of the
    // edge, or a null contact: each refused.
    OJ drop = j;
    drop["pieces"][0].erase("same_line_normals");
    BOOST_TEST(verdict_of(drop) == 1);
    OJ lie = j;
    lie["pieces"][0]["contact"] = "FF";
    BOOST_TEST(verdict_of(lie) == 1);
    OJ part = j;
    part["pieces"][0]["features"]["P1"] = OJ::array({7});
    BOOST_TEST(verdict_of(part) == 1);
    OJ none = j;
    none["pieces"][0]["contact"] = nullptr;
    BOOST_TEST(verdict_of(none) == 1);
    // And every mutation of the whole file, as for the bundled ones.
    mutate_and_report(j, "cubes_sharing_an_edge", false);
}

BOOST_AUTO_TEST_CASE(pieces_below_I2_are_proved_down_to_rho2_zero) {
    // A forged curve below I2. The tetrahedron-and-box scene with P1 and P2 swapped (tests/
    // data/tetra_on_box_curve_below_I2.json), I1 = [1/2, 10], I2 = [3/2, 4]. Swapping ρ1 and ρ2 in
    // test_hand_curves' derivation: (V,F) becomes (F,V) ρ2 = 9/5 − 2ρ1/5 for ρ1 ≥ 2, (E,E) becomes
    // ρ2 = (18 − 7ρ1)/4 on [18/13, 2], switching at (2, 1) — below lo2, where no overlap witness
    // reaches. The last piece reaches ρ2 = 0 at ρ1 = 9/2, where the seed (0,0,9/2) of the
    // tetrahedron lies on the top face z = 9/2 of the box scaled by 9/2: its zero witness.
    OJ j = fresh_partition("tetra_on_box_curve_below_I2.json");
    BOOST_TEST_REQUIRE(j["pieces"].size() == 3u);
    BOOST_TEST(j["pieces"][2]["contact"] == "FV");
    BOOST_TEST(j["pieces"][2]["intercept"] == "9/5");
    BOOST_TEST(j["switch_points"][1]["rho1"] == "2");
    BOOST_TEST(j["switch_points"][1]["rho2"] == "1");
    BOOST_TEST(!j["pieces"][1].contains("zero_witness"));
    const OJ& z = j["pieces"][2]["zero_witness"];
    BOOST_TEST(z["rho1"] == "9/2");
    BOOST_TEST(z["rho2"] == "0");
    BOOST_TEST((z["point"] == OJ::array({"0", "0", "9/2"})));
    // The forgery: the (E,E) piece stretched over [18/13, 10], hiding the switch point (2, 1) and
    // the (F,V) piece; accepted before, as the curve below lo2 was witnessed nowhere.
    OJ f = j;
    f["pieces"][1]["rho1"] = OJ::array({"18/13", "10"});
    f["pieces"][1]["rho1_double"] = OJ::array({18.0 / 13, 10.0});
    f["pieces"].erase(2);
    f["switch_points"].erase(1);
    f["curve_ends"][1] = OJ{{"rho1", "10"}, {"rho1_double", 10.0}, {"rho2", "-13"}, {"rho2_double", -13.0}};
    OJ sep = OJ::array();
    for (const auto& r : f["regions"]["separated"])
        if (r["piece"] != 2) sep.push_back(r);
    f["regions"]["separated"] = sep;
    BOOST_TEST(verdict_of(f) == 1);
    f["pieces"][1]["zero_witness"] = z;  // the true zero witness is not on this line
    BOOST_TEST(verdict_of(f) == 1);
    // A zero witness where ρ2 stays > 0, or none where it falls to 0: refused.
    OJ extra = j;
    extra["pieces"][1]["zero_witness"] = z;
    BOOST_TEST(verdict_of(extra) == 1);
    OJ none = j;
    none["pieces"][2].erase("zero_witness");
    BOOST_TEST(verdict_of(none) == 1);
}

BOOST_AUTO_TEST_CASE(a_curve_below_zero_at_lo1_is_anchored_by_a_witness) {
    // A curve <= 0 at lo1: the pieces must still be pinned, or any normal's line could be claimed
    // there. Cubes [-1,1]^3 and [1,3]×[-1,1]^2 (seeds at their
    // centres, d = (2,0,0)) touch on x = 1 + ρ1 = 3 − ρ2: the curve is ρ2 = 2 − ρ1, at or below 0
    // on I1 = [3, 4]. The witness at (3, 0) is P2's seed (2,0,0), inside P1(3) = [−3,3]^3.
    OJ j = fresh_partition("cubes_side_by_side_curve_below_zero.json");
    BOOST_TEST(j["curve_ends"][0]["rho2"] == "-1");
    BOOST_TEST(j["curve_ends"][0]["witness"]["rho2"] == "0");
    BOOST_TEST((j["curve_ends"][0]["witness"]["point"] == OJ::array({"2", "0", "0"})));
    BOOST_TEST(!j["curve_ends"][1].contains("witness"));
    // The forgery: another normal's line, (−1,0,0) pointing away from P2 (ρ2 = −2 − ρ1), and no
    // witness; refused. With the witness kept, the line's end no longer meets it: refused too.
    OJ f = j;
    f["pieces"][0]["normal"] = OJ::array({"-1", "0", "0"});
    f["pieces"][0]["intercept"] = "-2";
    f["pieces"][0]["intercept_double"] = -2.0;
    f["curve_ends"][0]["rho2"] = "-5";
    f["curve_ends"][0]["rho2_double"] = -5.0;
    f["curve_ends"][1]["rho2"] = "-6";
    f["curve_ends"][1]["rho2_double"] = -6.0;
    BOOST_TEST(verdict_of(f) == 1);
    f["curve_ends"][0].erase("witness");
    BOOST_TEST(verdict_of(f) == 1);
}

BOOST_AUTO_TEST_CASE(below_rho2_zero_the_curve_is_one_line) {
    // tests/data/boxes_curve_goes_on_below_zero.json, derived in test_hand_curves: the curve is
    // ρ2 = 3 − ρ1 (normal (1,0,0)) on I1 = [1, 6], reaching 0 at ρ1 = 3; the line of normal (0,1,0),
    // ρ2 = (1 − ρ1)/2, overtakes it at (5, −2), below ρ2 = 0. The engine once wrote that switch;
    // the curve now goes on as one line there, and a certificate with a switch below 0 is refused.
    OJ j = fresh_partition("boxes_curve_goes_on_below_zero.json");
    BOOST_TEST_REQUIRE(j["pieces"].size() == 1u);
    BOOST_TEST(j["switch_points"].empty());
    BOOST_TEST(j["pieces"][0]["intercept"] == "3");
    BOOST_TEST(j["pieces"][0]["zero_witness"]["rho1"] == "3");
    OJ f = j;
    f["pieces"][0]["rho1"] = OJ::array({"1", "5"});
    f["pieces"][0]["rho1_double"] = OJ::array({1.0, 5.0});
    OJ q = OJ::object();
    q["rho1"] = OJ::array({"5", "6"});
    q["rho1_double"] = OJ::array({5.0, 6.0});
    q["slope"] = "-1/2", q["slope_double"] = -0.5, q["intercept"] = "1/2", q["intercept_double"] = 0.5;
    q["contact"] = nullptr;
    q["closed_form"] = j["pieces"][0]["closed_form"];
    q["normal"] = OJ::array({"0", "1", "0"});
    q["h1"] = "1", q["h1_double"] = 1.0, q["h2"] = "2", q["h2_double"] = 2.0;
    q["support_vertices"] = OJ{{"P1", 2}, {"P2", 0}};
    f["pieces"].push_back(q);
    f["switch_points"].push_back(
        OJ{{"rho1", "5"}, {"rho1_double", 5.0}, {"rho2", "-2"}, {"rho2_double", -2.0}, {"contact", nullptr}});
    f["curve_ends"][1]["rho2"] = "-5/2";
    f["curve_ends"][1]["rho2_double"] = -2.5;
    BOOST_TEST(verdict_of(f) == 1);
    std::string msg;
    scalecert_check::check_text(f.dump(1), msg);
    BOOST_TEST(msg.find("from rho2 = 0 on, the curve goes on as one line") != std::string::npos, msg);
}

BOOST_AUTO_TEST_CASE(where_the_envelope_turns_at_zero_the_piece_reaching_it_goes_on) {
    // tests/data/boxes_curve_turns_at_zero.json: P1 = [−1,1]^3, P2 = [2,4] × [1,5] × [−1,1] (seeds
    // at the centres, d = (3,3,0)). n = (1,0,0): h1 = h2 = 1, n·d = 3, ρ2 = 3 − ρ1; n = (0,1,0):
    // h1 = 1, h2 = 2, n·d = 3, ρ2 = (3 − ρ1)/2. Both reach 0 at ρ1 = 3, where the envelope turns.
    // The curve is the piece reaching 0, 3 − ρ1 (pinned by its contact and zero witnesses), on all
    // of I1 = [1, 6]; the next line would be pinned by nothing (a forgery could swap it for
    // (1,1,0)'s), so a switch at ρ2 = 0 is refused.
    OJ j = fresh_partition("boxes_curve_turns_at_zero.json");
    BOOST_TEST_REQUIRE(j["pieces"].size() == 1u);
    BOOST_TEST(j["pieces"][0]["intercept"] == "3");
    BOOST_TEST(j["switch_points"].empty());
    BOOST_TEST(j["pieces"][0]["zero_witness"]["rho1"] == "3");
    OJ f = j;
    f["pieces"][0]["rho1"] = OJ::array({"1", "3"});
    f["pieces"][0]["rho1_double"] = OJ::array({1.0, 3.0});
    OJ q = OJ::object();
    q["rho1"] = OJ::array({"3", "6"});
    q["rho1_double"] = OJ::array({3.0, 6.0});
    q["slope"] = "-1/2", q["slope_double"] = -0.5, q["intercept"] = "3/2", q["intercept_double"] = 1.5;
    q["contact"] = nullptr;
    q["closed_form"] = j["pieces"][0]["closed_form"];
    q["normal"] = OJ::array({"0", "1", "0"});
    q["h1"] = "1", q["h1_double"] = 1.0, q["h2"] = "2", q["h2_double"] = 2.0;
    q["support_vertices"] = OJ{{"P1", 2}, {"P2", 0}};
    f["pieces"].push_back(q);
    f["switch_points"].push_back(
        OJ{{"rho1", "3"}, {"rho1_double", 3.0}, {"rho2", "0"}, {"rho2_double", 0.0}, {"contact", nullptr}});
    f["curve_ends"][1]["rho2"] = "-3/2";
    f["curve_ends"][1]["rho2_double"] = -1.5;
    std::string msg;
    BOOST_TEST(scalecert_check::check_text(f.dump(1), msg) == 1);
    BOOST_TEST(msg.find("from rho2 = 0 on, the curve goes on as one line") != std::string::npos, msg);
}

BOOST_AUTO_TEST_CASE(same_line_normals_are_few_and_each_shrinks_the_features) {
    // Cubes sharing an edge: (1,0,0) and (0,1,0) give the line; (1,1,0) and (2,1,0), in their
    // normal cone, give it too, but add nothing once the edge is reached. Listing the same normal
    // again, or the piece's own normal, or five, made the checker scan every vertex for each
    // (30,000 repeats of one normal in an 845 KB file would take 496 s).
    OJ j = fresh_partition("cubes_sharing_an_edge.json");
    const OJ other = j["pieces"][0]["same_line_normals"][0];
    OJ twice = j;
    twice["pieces"][0]["same_line_normals"].push_back(other);
    BOOST_TEST(verdict_of(twice) == 1);
    OJ own = j;
    own["pieces"][0]["same_line_normals"].push_back(j["pieces"][0]["normal"]);
    BOOST_TEST(verdict_of(own) == 1);
    OJ cone = j;
    cone["pieces"][0]["same_line_normals"] =
        OJ::array({OJ::array({"1", "1", "0"})});  // shrinks the face to the edge itself
    BOOST_TEST(verdict_of(cone) == 0);
    cone["pieces"][0]["same_line_normals"].push_back(OJ::array({"2", "1", "0"}));  // shrinks nothing more
    BOOST_TEST(verdict_of(cone) == 1);
    OJ five = j;
    for (int k = 0; k < 4; ++k)
        five["pieces"][0]["same_line_normals"].push_back(OJ::array({"1", std::to_string(k + 2), "0"}));
    BOOST_TEST(verdict_of(five) == 1);
}

BOOST_AUTO_TEST_SUITE_END()
