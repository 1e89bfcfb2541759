// The renderer registry: ids, order, pairs and who deviates, for any number
// of renderers (renderers/registry.h).
#include <gtest/gtest.h>

#include <set>

#include "renderers/registry.h"
#include "scene_file/scene_loader.h"

using namespace xval;
using namespace xval::renderers;

namespace {

Renderer stub(const std::string& id, const std::string& name, bool reference = false) {
  Renderer r;
  r.id = id;
  r.display_name = name;
  r.reference = reference;
  r.render = [](const Scene&, const RenderRequest&, RenderInfo*) { return Image(1, 1, false); };
  return r;
}

std::vector<const Renderer*> pointers(const std::vector<Renderer>& rs) {
  std::vector<const Renderer*> out;
  for (const auto& r : rs) out.push_back(&r);
  return out;
}

}  // namespace

TEST(Registry, IdsAreUniqueWellFormedAndOneIsTheReference) {
  const Registry& reg = registry();
  ASSERT_GE(reg.size(), 3u);
  std::set<std::string> seen;
  int references = 0;
  for (const Renderer& r : reg.all()) {
    EXPECT_TRUE(seen.insert(r.id).second) << "duplicate id " << r.id;
    EXPECT_FALSE(r.display_name.empty()) << r.id;
    EXPECT_FALSE(r.summary.empty()) << r.id;
    EXPECT_TRUE(bool(r.render)) << r.id;
    for (char c : r.id) EXPECT_TRUE((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-') << r.id;
    references += r.reference;
  }
  EXPECT_EQ(references, 1);
  EXPECT_EQ(reg.reference().id, reg.ids().front());
}

// validate's jobs and pairs (results.json keys) are these, in this order.
TEST(Registry, BuiltInOrderAndRoles) {
  const Registry& reg = registry();
  EXPECT_EQ(reg.everySceneIds(), (std::vector<std::string>{"reference", "povray", "blender", "eevee", "gl"}));
  std::vector<std::string> compared = reg.ids();
  compared.erase(compared.begin());
  EXPECT_EQ(reg.comparedIds(), compared);
  ASSERT_NE(reg.find("blender-native"), nullptr);
  EXPECT_FALSE(reg.find("blender-native")->every_scene);
  ASSERT_NE(reg.find("eevee-native"), nullptr);
  EXPECT_FALSE(reg.find("eevee-native")->every_scene);
  EXPECT_EQ(reg.find("mitsuba"), nullptr);
  try {
    reg.at("mitsuba");
    FAIL() << "no error for an unknown id";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("\"mitsuba\": unknown, expected one of reference, povray"),
              std::string::npos)
        << e.what();
  }
}

TEST(Registry, AddRefusesBadDuplicateAndSecondReference) {
  Registry reg;
  reg.add(stub("a", "A", true));
  EXPECT_THROW(reg.add(stub("a", "A again")), std::invalid_argument);
  EXPECT_THROW(reg.add(stub("b", "B", true)), std::invalid_argument);
  EXPECT_THROW(reg.add(stub("", "empty")), std::invalid_argument);
  EXPECT_THROW(reg.add(stub("Upper", "U")), std::invalid_argument);
  EXPECT_THROW(reg.add(stub("a/b", "slash")), std::invalid_argument);
  Renderer no_render = stub("c", "C");
  no_render.render = nullptr;
  EXPECT_THROW(reg.add(no_render), std::invalid_argument);
  reg.add(stub("b", "B"));
  EXPECT_EQ(reg.ids(), (std::vector<std::string>{"a", "b"}));
}

// Renderers added at run time are in the registry's listings, its pairs,
// and the keys a scene's `tolerances` may use.
TEST(Registry, RunTimeRendererIsAToleranceKey) {
  const std::string scene = R"({"name": "t",
    "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "width": 8, "height": 8},
    "objects": [{"shape": "sphere"}], "material": {"model": {"type": "lambert"}},
    "lights": [{"type": "point", "position": [1, 2, 3]}],
    "tolerances": {"user-renderer": {"max_abs_16bit": 8, "reason": "a long enough reason for the test"}}})";
  EXPECT_THROW(parseScene(scene, "t.json"), SceneError);
  // Restricted to some scenes, so that the every-scene list the other
  // tests check is unchanged when they run in this process after it.
  Renderer user = stub("user-renderer", "User");
  user.every_scene = false;
  registry().add(user);
  const Scene s = parseScene(scene, "t.json");
  ASSERT_EQ(s.tolerances.size(), 1u);
  EXPECT_EQ(s.tolerances[0].renderer, "user-renderer");
  EXPECT_EQ(registry().comparedIds().back(), "user-renderer");
}

TEST(Registry, PairsAreEveryUnorderedPairInOrder) {
  const Registry& reg = registry();
  std::vector<std::string> keys;
  const auto rs = reg.everySceneRenderers();
  for (const RendererPair& p : unorderedPairs(rs.size())) keys.push_back(pairKey(*rs[p.a], *rs[p.b]));
  EXPECT_EQ(keys, (std::vector<std::string>{"reference-povray", "reference-blender", "reference-eevee", "reference-gl",
                                            "povray-blender", "povray-eevee", "povray-gl", "blender-eevee",
                                            "blender-gl", "eevee-gl"}));
  for (size_t n = 0; n < 7; ++n) {
    const auto pairs = unorderedPairs(n);
    EXPECT_EQ(pairs.size(), n * (n - 1) / 2);
    std::set<std::pair<size_t, size_t>> seen;
    for (const auto& p : pairs) {
      EXPECT_LT(p.a, p.b);
      EXPECT_LT(p.b, n);
      EXPECT_TRUE(seen.insert({p.a, p.b}).second);
    }
  }
}

// Three renderers: the answers validate has always given.
TEST(Attribution, ThreeRenderers) {
  const auto& reg = registry();
  auto rs = reg.everySceneRenderers();
  ASSERT_GE(rs.size(), 3u);
  rs.resize(3);  // reference, povray, blender
  // verdicts: reference-povray, reference-blender, povray-blender
  EXPECT_EQ(attribute(rs, {1, 1, 1}), "all three agree");
  EXPECT_EQ(attribute(rs, {0, 1, 0}), "POV-Ray deviates (reference and Blender agree)");
  EXPECT_EQ(attribute(rs, {1, 0, 0}), "Blender deviates (reference and POV-Ray agree)");
  EXPECT_EQ(attribute(rs, {0, 0, 1}), "the reference renderer deviates (POV-Ray and Blender agree)");
  // No majority: the failing pairs are named.
  EXPECT_EQ(attribute(rs, {0, 0, 0}), "no two renderers agree");
  EXPECT_EQ(attribute(rs, {1, 1, 0}), "POV-Ray and Blender disagree (the other pairs agree)");
  EXPECT_EQ(attribute(rs, {1, 0, 1}), "the reference renderer and Blender disagree (the other pairs agree)");
  EXPECT_EQ(attribute(rs, {0, 1, 1}), "the reference renderer and POV-Ray disagree (the other pairs agree)");
  EXPECT_EQ(attribute(rs, {1, -1, 1}), "incomplete (a renderer failed)");
  EXPECT_EQ(attribute(rs, {0, 0, -1}), "incomplete (a renderer failed)");
  EXPECT_THROW(attribute(rs, {1, 1}), std::invalid_argument);
}

TEST(Attribution, TwoRenderers) {
  const std::vector<Renderer> rs{stub("a", "A", true), stub("b", "B")};
  EXPECT_EQ(attribute(pointers(rs), {1}), "both agree");
  // Two cannot tell which of them deviates.
  EXPECT_EQ(attribute(pointers(rs), {0}), "A and B disagree");
  EXPECT_EQ(attribute(pointers(rs), {-1}), "incomplete (a renderer failed)");
}

TEST(Attribution, FourAndFiveRenderersTheMajority) {
  const std::vector<Renderer> four{stub("a", "A", true), stub("b", "B"), stub("c", "C"), stub("d", "D")};
  const auto rs = pointers(four);
  // pairs: ab ac ad bc bd cd
  EXPECT_EQ(attribute(rs, {1, 1, 1, 1, 1, 1}), "all 4 agree");
  EXPECT_EQ(attribute(rs, {1, 1, 0, 1, 0, 0}), "D deviates (A, B and C agree)");
  EXPECT_EQ(attribute(rs, {0, 0, 0, 1, 1, 1}), "A deviates (B, C and D agree)");
  // D disagrees with A and B only: not with all of the majority.
  EXPECT_EQ(attribute(rs, {1, 1, 0, 1, 0, 1}), "A and D disagree; B and D disagree");
  // Two against two: no majority.
  EXPECT_EQ(attribute(rs, {1, 0, 0, 0, 0, 1}), "A and C disagree; A and D disagree; B and C disagree; B and D disagree");
  // Five: a majority of three, two deviating.
  const std::vector<Renderer> five{stub("a", "A", true), stub("b", "B"), stub("c", "C"), stub("d", "D"),
                                   stub("e", "E")};
  // pairs: ab ac ad ae bc bd be cd ce de; A, B, C agree; D and E fail against them.
  EXPECT_EQ(attribute(pointers(five), {1, 1, 0, 0, 1, 0, 0, 0, 0, 1}), "D and E deviate (A, B and C agree)");
}

// deviating: the indices attribute names as deviating, none without a
// majority (validate prints the golden update step for them only).
TEST(Attribution, DeviatingAreTheOnesOutsideTheMajority) {
  // reference-povray, reference-blender, povray-blender
  EXPECT_EQ(deviating(3, {0, 0, 1}), (std::vector<size_t>{0}));
  EXPECT_EQ(deviating(3, {0, 1, 0}), (std::vector<size_t>{1}));
  EXPECT_TRUE(deviating(3, {1, 1, 1}).empty());
  EXPECT_TRUE(deviating(3, {0, 0, 0}).empty());
  EXPECT_TRUE(deviating(3, {0, 0, -1}).empty());
  EXPECT_TRUE(deviating(2, {0}).empty());  // two: neither is to blame on its own
  EXPECT_EQ(deviating(5, {1, 1, 0, 0, 1, 0, 0, 0, 0, 1}), (std::vector<size_t>{3, 4}));
  EXPECT_THROW(deviating(3, {1, 1}), std::invalid_argument);
}

// Soft failures (a pair failing only on the fraction within tolerance,
// image/pair_failure.h) beside hard ones (issue #36): the renderer with
// unexplained differences against the others is the one named.
TEST(Attribution, SoftFailuresDoNotHideTheRendererThatFailsHard) {
  const std::vector<Renderer> three{stub("reference", "reference", true), stub("gl", "OpenGL"),
                                    stub("mutant", "mutant")};
  const auto rs = pointers(three);
  const int pass = kPairPasses, hard = kPairFails, soft = kPairFailsOnlyOnFraction;
  // reference-gl, reference-mutant, gl-mutant: reference and OpenGL fail
  // on the fraction alone, the mutant fails hard against both. The
  // majority of pass verdicts found nobody ("no two renderers agree").
  EXPECT_EQ(attribute(rs, {soft, hard, hard}),
            "mutant deviates (unexplained differences against reference and OpenGL; reference and OpenGL fail only "
            "on the fraction within tolerance)");
  EXPECT_EQ(deviating(3, {soft, hard, hard}), (std::vector<size_t>{2}));
  // The mutant passes against OpenGL (its fault is where OpenGL's pixels
  // are explained) and fails hard against the reference, which fails
  // against OpenGL on the fraction alone: the majority of pass verdicts
  // blamed the reference. Nobody is singled out; the hard pair is named.
  EXPECT_TRUE(deviating(3, {soft, hard, pass}).empty());
  EXPECT_EQ(attribute(rs, {soft, hard, pass}),
            "reference and OpenGL disagree only on the fraction within tolerance; reference and mutant disagree");
  // Every failure soft: the majority of pass verdicts, said to be about
  // the fraction.
  EXPECT_EQ(attribute(rs, {pass, soft, soft}),
            "mutant deviates, only on the fraction within tolerance (reference and OpenGL agree)");
  EXPECT_EQ(deviating(3, {pass, soft, soft}), (std::vector<size_t>{2}));
  EXPECT_EQ(attribute(rs, {soft, soft, soft}),
            "reference and OpenGL disagree only on the fraction within tolerance; reference and mutant disagree only on "
            "the fraction within tolerance; OpenGL and mutant disagree only on the fraction within tolerance");
  // Hard failures against a majority that passes: as before.
  EXPECT_EQ(attribute(rs, {pass, hard, hard}), "mutant deviates (reference and OpenGL agree)");
  // A mutant failing soft against one and hard against the other: no majority.
  EXPECT_TRUE(deviating(3, {pass, soft, hard}).empty());
  const std::vector<Renderer> two{stub("a", "A", true), stub("b", "B")};
  EXPECT_EQ(attribute(pointers(two), {soft}), "A and B disagree only on the fraction within tolerance");
  EXPECT_TRUE(deviating(2, {soft}).empty());
}

// Four renderers: two correct ones fail among themselves on the fraction,
// the other pairs of the majority pass, the mutant fails hard against all.
TEST(Attribution, SoftFailuresInsideALargerMajority) {
  const std::vector<Renderer> four{stub("a", "A", true), stub("b", "B"), stub("c", "C"), stub("d", "D")};
  const int pass = kPairPasses, hard = kPairFails, soft = kPairFailsOnlyOnFraction;
  // pairs: ab ac ad bc bd cd
  EXPECT_EQ(attribute(pointers(four), {soft, pass, hard, pass, hard, hard}),
            "D deviates (unexplained differences against A, B and C; A and B fail only on the fraction within "
            "tolerance)");
  EXPECT_EQ(deviating(4, {soft, pass, hard, pass, hard, hard}), (std::vector<size_t>{3}));
}

// A scene's `renderers` field: a golden set stands in for the renderer
// whose images it stores (issue #30: `golden` was left out of a scene
// meant for the reference).
TEST(MeantFor, AGoldenSetStandsInForTheRendererItStores) {
  const std::vector<std::string> limited{"reference", "gl", "blender-import"};
  EXPECT_TRUE(meantFor(limited, registry().at("reference")));
  EXPECT_FALSE(meantFor(limited, registry().at("povray")));
  EXPECT_TRUE(meantFor(limited, registry().at("golden")));
  EXPECT_TRUE(meantFor(limited, registry().at("golden-gl")));
  EXPECT_FALSE(meantFor(limited, registry().at("golden-povray")));
  EXPECT_TRUE(meantFor({}, registry().at("golden-povray")));  // no field: every renderer
  EXPECT_FALSE(meantFor(limited, stub("golden-like", "not a golden set")));
}

// Pair ids join the renderers' ids with '-', which ids contain: two pairs
// that would share an id are found (issue #34.11).
TEST(Registry, PairKeyClashIsFound) {
  using xval::renderers::pairKeyClash;
  EXPECT_FALSE(pairKeyClash({"reference", "m-n", "n", "reference-m"}).has_value());
  const auto clash = pairKeyClash({"reference", "m-z", "reference-m", "z"});
  ASSERT_TRUE(clash.has_value());
  EXPECT_EQ(clash->first.a, 0u);   // reference
  EXPECT_EQ(clash->first.b, 1u);   // + m-z
  EXPECT_EQ(clash->second.a, 2u);  // reference-m
  EXPECT_EQ(clash->second.b, 3u);  // + z
  // The built-in renderers and their golden sets: no clash.
  EXPECT_FALSE(pairKeyClash(registry().ids()).has_value());
}
