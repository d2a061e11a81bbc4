// The shading model registry (core/models/models.h): names are unique and found again, unknown
// names are refused with the list of known ones, lit models round-trip through their names,
// sample materials are the ones samples.h makes, uniformTexel inverts toAshikhminShirley's
// exponent mapping, and shadeLitModel's factored Ward equals the direct eq. 5b evaluation
// (the same function of the half vector for unit vectors).
#include "core/error.h"
#include "core/models/models.h"
#include "core/models/samples.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <set>
#include <string>

namespace aniso
{
TEST(ModelsRegistry, NamesAreUniqueAndFound)
{
  const auto& models = shadingModels();
  ASSERT_FALSE(models.empty());
  EXPECT_EQ(models.front().name, kEnvironmentModel);
  std::set<std::string_view> names;
  for (const ShadingModelInfo& model : models)
  {
    EXPECT_TRUE(names.insert(model.name).second) << model.name;
    EXPECT_EQ(findShadingModel(model.name), &model);
    EXPECT_FALSE(model.title.empty());
    EXPECT_FALSE(model.description.empty());
    EXPECT_TRUE(model.environment || model.lights) << model.name;
  }
  EXPECT_EQ(findShadingModel("no-such-model"), nullptr);
  try
  {
    shadingModel("no-such-model", "--model");
    FAIL() << "an unknown model was accepted";
  }
  catch (const Error& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("--model: ", 0), 0u) << message;
    EXPECT_NE(message.find("banks"), std::string::npos) << message;
  }
}

TEST(ModelsRegistry, LitModelsRoundTripAndAreRegistered)
{
  for (LitModel model : {LitModel::AshikhminShirley, LitModel::Banks, LitModel::BlinnPhong,
                         LitModel::Ward, LitModel::HeidrichSeidel})
  {
    const std::string_view name = litModelName(model);
    LitModel back = LitModel::AshikhminShirley;
    ASSERT_TRUE(litModelFromName(name, back)) << name;
    EXPECT_EQ(back, model);
    const ShadingModelInfo* info = findShadingModel(name);
    ASSERT_NE(info, nullptr) << name;
    EXPECT_TRUE(info->lights);
  }
  LitModel unused;
  EXPECT_FALSE(litModelFromName(kEnvironmentModel, unused));
}

TEST(ModelsRegistry, SampleMaterialsAreTheSamplesOfTheCore)
{
  for (const SampleMaterialInfo& info : sampleMaterials())
  {
    const SvMaps maps = makeSampleMaterial(info.name, "--sample-material");
    EXPECT_FALSE(maps.tangentAlpha.empty()) << info.name;
    EXPECT_FALSE(maps.albedoSpecular.empty()) << info.name;
    EXPECT_FALSE(maps.normal.empty()) << info.name;
  }
  const SvTexel latitudinal =
      sampleSvMaps(makeSampleMaterial("brushed-latitudinal", "m"), {0.3, 0.6});
  EXPECT_EQ(latitudinal.tangent, brushedMetal(BrushDirection::Latitudinal).tangent);
  const SvTexel longitudinal =
      sampleSvMaps(makeSampleMaterial("brushed-longitudinal", "m"), {0.3, 0.6});
  EXPECT_EQ(longitudinal.tangent, brushedMetal(BrushDirection::Longitudinal).tangent);
  EXPECT_EQ(makeSampleMaterial("marble", "m").albedoSpecular.data,
            veinedMarble(512).albedoSpecular.data);
  EXPECT_THROW(makeSampleMaterial("granite", "--sample-material"), Error);
}

TEST(ModelsRegistry, UniformTexelInvertsTheExponentMapping)
{
  for (double nu : {0.0, 1.0, 50.0, 1000.0, 20000.0})
  {
    const AsLobe lobe{nu, 70.0};
    const SvTexel texel = uniformTexel(lobe, glm::dvec3(0.2, 0.4, 0.6), glm::dvec3(0.1));
    const AsMaterial as = toAshikhminShirley(texel);
    EXPECT_NEAR(as.lobe.nu, nu, 1e-9 * (1.0 + nu));
    EXPECT_NEAR(as.lobe.nv, 70.0, 1e-9 * 71.0);
    EXPECT_DOUBLE_EQ(texel.specular, 0.4);
  }
}

TEST(ModelsRegistry, FactoredWardEqualsDirectWard)
{
  SvTexel texel;
  texel.alphaX = 0.1;
  texel.alphaY = 0.35;
  texel.diffuse = glm::dvec3(0.2);
  texel.specular = 0.7;
  const Frame frame = Frame::fromNormalTangent(glm::normalize(glm::dvec3(0.3, -0.2, 1.0)),
                                               glm::dvec3(1.0, 0.5, 0.0));
  const std::vector<Light> lights = {parseLight("dir:-1,-1,2:2"), parseLight("point:1,-2,2:5")};
  const glm::dvec3 position(0.1, 0.0, 0.0);
  for (const glm::dvec3& view :
       {glm::dvec3(0.0, -1.0, 1.0), glm::dvec3(0.5, -1.0, 0.3), glm::dvec3(-0.2, 0.1, 1.0)})
  {
    const glm::dvec3 v = glm::normalize(view);
    const glm::dvec3 factored = shadeLitModel(LitModel::Ward, texel, frame, position, v, lights);
    const glm::dvec3 direct = shadeWard(toWard(texel), frame, position, v, lights);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(factored[c], direct[c], 1e-12 * (1.0 + std::abs(direct[c])));
    }
  }
}
} // namespace aniso
