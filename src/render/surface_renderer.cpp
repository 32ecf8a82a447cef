#include "lbmshape/render/surface_renderer.hpp"

#include <cstring>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/stopwatch.hpp"
#include "lbmshape/gpu/gpu_buffer.hpp"
#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/gpu/gpu_image.hpp"
#include "lbmshape/gpu/shader_registry.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/shaders/render_interface.h"

namespace lbmshape::render {
namespace {

constexpr vk::Format kColourFormat = vk::Format::eR8G8B8A8Unorm;

vk::SampleCountFlagBits multisampling(const vk::PhysicalDeviceLimits& limits)
{
  const vk::SampleCountFlags both = limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts;
  return (both & vk::SampleCountFlagBits::e4) ? vk::SampleCountFlagBits::e4 : vk::SampleCountFlagBits::e1;
}

vk::Format depthFormat(const vk::raii::PhysicalDevice& device)
{
  for (vk::Format f : {vk::Format::eD32Sfloat, vk::Format::eX8D24UnormPack32, vk::Format::eD16Unorm})
    if (device.getFormatProperties(f).optimalTilingFeatures & vk::FormatFeatureFlagBits::eDepthStencilAttachment)
      return f;
  throw DeviceError("the Vulkan device has no depth format to draw pictures with");
}

// Normals per triangle corner: the area-weighted mean of the triangles
// around the vertex that meet this one at less than the crease angle. Smooth
// surfaces shade smoothly, and a box or a machined part keeps its edges.
constexpr double kCreaseCosine = 0.5;  // 60 degrees

std::vector<glm::vec3> cornerNormals(const TriangleMesh& mesh)
{
  const size_t triangles = mesh.triangleCount();
  std::vector<glm::dvec3> faceArea(triangles);
  std::vector<uint32_t> start(mesh.vertexCount() + 1, 0), around(3 * triangles);
  for (size_t t = 0; t < triangles; ++t) {
    faceArea[t] = triangleAreaVector(mesh, mesh.triangles[t]);
    for (int k = 0; k < 3; ++k) ++start[mesh.triangles[t][k] + 1];
  }
  for (size_t v = 0; v < mesh.vertexCount(); ++v) start[v + 1] += start[v];
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (size_t t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k) around[fill[mesh.triangles[t][k]]++] = uint32_t(t);
  std::vector<glm::vec3> normals(3 * triangles);
#pragma omp parallel for schedule(static)
  for (long t = 0; t < long(triangles); ++t) {
    const glm::dvec3 own = glm::length(faceArea[size_t(t)]) > 0 ? glm::normalize(faceArea[size_t(t)]) : glm::dvec3(0.0);
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[size_t(t)][k];
      glm::dvec3 sum(0.0);
      for (uint32_t i = start[v]; i < start[v + 1]; ++i) {
        const glm::dvec3& other = faceArea[around[i]];
        const double length = glm::length(other);
        if (length > 0 && glm::dot(other, own) >= kCreaseCosine * length) sum += other;
      }
      normals[size_t(t) * 3 + size_t(k)] = glm::vec3(glm::length(sum) > 0 ? glm::normalize(sum) : own);
    }
  }
  return normals;
}

// Every panel's triangles in one vertex buffer, three vertices each (their
// normals differ across creases), written straight into the buffer's mapped
// memory: a million triangles are 108 MB of vertices.
struct Draw {
  uint32_t firstVertex = 0, vertexCount = 0;
  size_t cell = 0;
};

size_t cornerCount(const Picture& picture)
{
  size_t corners = 0;
  for (const Panel& p : picture.panels) corners += 3 * p.mesh->triangleCount();
  return corners;
}

std::vector<Draw> gather(const Picture& picture, const Framing& framing, float* vertices)
{
  std::vector<Draw> draws;
  size_t first = 0;
  for (size_t cell = 0; cell < picture.panels.size(); ++cell) {
    const Panel& panel = picture.panels[cell];
    const TriangleMesh& mesh = *panel.mesh;
    const std::vector<glm::vec3> normals = cornerNormals(mesh);
    float* out = vertices + first * RENDER_VERTEX_FLOATS;
#pragma omp parallel for schedule(static)
    for (long c = 0; c < long(3 * mesh.triangleCount()); ++c) {
      const uint32_t v = mesh.triangles[size_t(c) / 3][int(c % 3)];
      const glm::vec3 p((mesh.positions[v] - framing.centre) / framing.unit), n = normals[size_t(c)];
      const glm::vec3 colour = panel.colours.empty() ? plainSurfaceColour() : panel.colours[v];
      float* o = out + size_t(c) * RENDER_VERTEX_FLOATS;
      o[0] = p.x, o[1] = p.y, o[2] = p.z, o[3] = n.x, o[4] = n.y, o[5] = n.z, o[6] = colour.r, o[7] = colour.g,
      o[8] = colour.b;
    }
    if (mesh.triangleCount() > 0) draws.push_back({uint32_t(first), uint32_t(3 * mesh.triangleCount()), cell});
    first += 3 * mesh.triangleCount();
  }
  return draws;
}

vk::raii::RenderPass makeRenderPass(const vk::raii::Device& device, vk::SampleCountFlagBits samples, vk::Format depth)
{
  const bool resolve = samples != vk::SampleCountFlagBits::e1;
  std::vector<vk::AttachmentDescription> attachments = {
      {{},
       kColourFormat,
       samples,
       vk::AttachmentLoadOp::eClear,
       resolve ? vk::AttachmentStoreOp::eDontCare : vk::AttachmentStoreOp::eStore,
       vk::AttachmentLoadOp::eDontCare,
       vk::AttachmentStoreOp::eDontCare,
       vk::ImageLayout::eUndefined,
       resolve ? vk::ImageLayout::eColorAttachmentOptimal : vk::ImageLayout::eTransferSrcOptimal},
      {{},
       depth,
       samples,
       vk::AttachmentLoadOp::eClear,
       vk::AttachmentStoreOp::eDontCare,
       vk::AttachmentLoadOp::eDontCare,
       vk::AttachmentStoreOp::eDontCare,
       vk::ImageLayout::eUndefined,
       vk::ImageLayout::eDepthStencilAttachmentOptimal}};
  if (resolve)
    attachments.push_back({{},
                           kColourFormat,
                           vk::SampleCountFlagBits::e1,
                           vk::AttachmentLoadOp::eDontCare,
                           vk::AttachmentStoreOp::eStore,
                           vk::AttachmentLoadOp::eDontCare,
                           vk::AttachmentStoreOp::eDontCare,
                           vk::ImageLayout::eUndefined,
                           vk::ImageLayout::eTransferSrcOptimal});
  const vk::AttachmentReference colour(0, vk::ImageLayout::eColorAttachmentOptimal);
  const vk::AttachmentReference depthRef(1, vk::ImageLayout::eDepthStencilAttachmentOptimal);
  const vk::AttachmentReference resolved(2, vk::ImageLayout::eColorAttachmentOptimal);
  vk::SubpassDescription subpass({}, vk::PipelineBindPoint::eGraphics, {}, colour,
                                 resolve ? resolved : vk::ArrayProxyNoTemporaries<const vk::AttachmentReference>(),
                                 &depthRef);
  const vk::PipelineStageFlags attachmentStages = vk::PipelineStageFlagBits::eColorAttachmentOutput |
                                                  vk::PipelineStageFlagBits::eEarlyFragmentTests |
                                                  vk::PipelineStageFlagBits::eLateFragmentTests;
  const std::array<vk::SubpassDependency, 2> dependencies = {
      vk::SubpassDependency(
          VK_SUBPASS_EXTERNAL, 0, attachmentStages, attachmentStages, {},
          vk::AccessFlagBits::eColorAttachmentWrite | vk::AccessFlagBits::eDepthStencilAttachmentWrite),
      vk::SubpassDependency(0, VK_SUBPASS_EXTERNAL, vk::PipelineStageFlagBits::eColorAttachmentOutput,
                            vk::PipelineStageFlagBits::eTransfer, vk::AccessFlagBits::eColorAttachmentWrite,
                            vk::AccessFlagBits::eTransferRead)};
  return vk::raii::RenderPass(device, vk::RenderPassCreateInfo({}, attachments, subpass, dependencies));
}

vk::raii::Pipeline makePipeline(gpu::GpuContext& context, const vk::raii::PipelineLayout& layout,
                                const vk::raii::RenderPass& pass, vk::SampleCountFlagBits samples, bool lines,
                                bool biased)
{
  const vk::raii::Device& device = context.device();
  const std::span<const uint32_t> vertexCode = gpu::embeddedSpirv("render_surface_vert");
  const std::span<const uint32_t> fragmentCode = gpu::embeddedSpirv("render_surface_frag");
  vk::raii::ShaderModule vertex(device, vk::ShaderModuleCreateInfo({}, vertexCode.size_bytes(), vertexCode.data()));
  vk::raii::ShaderModule fragment(device,
                                  vk::ShaderModuleCreateInfo({}, fragmentCode.size_bytes(), fragmentCode.data()));
  const uint32_t linesWord = lines ? VK_TRUE : VK_FALSE;
  const vk::SpecializationMapEntry entry(RENDER_SPEC_LINES, 0, sizeof(uint32_t));
  const vk::SpecializationInfo specialization(1, &entry, sizeof(uint32_t), &linesWord);
  const std::array<vk::PipelineShaderStageCreateInfo, 2> stages = {
      vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eVertex, *vertex, "main"),
      vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eFragment, *fragment, "main", &specialization)};
  const vk::VertexInputBindingDescription binding(0, RENDER_VERTEX_FLOATS * sizeof(float),
                                                  vk::VertexInputRate::eVertex);
  const std::array<vk::VertexInputAttributeDescription, 3> attributes = {
      vk::VertexInputAttributeDescription(RENDER_LOCATION_POSITION, 0, vk::Format::eR32G32B32Sfloat, 0),
      vk::VertexInputAttributeDescription(RENDER_LOCATION_NORMAL, 0, vk::Format::eR32G32B32Sfloat, 3 * sizeof(float)),
      vk::VertexInputAttributeDescription(RENDER_LOCATION_COLOUR, 0, vk::Format::eR32G32B32Sfloat, 6 * sizeof(float))};
  const vk::PipelineVertexInputStateCreateInfo vertexInput({}, binding, attributes);
  const vk::PipelineInputAssemblyStateCreateInfo assembly({}, vk::PrimitiveTopology::eTriangleList);
  const vk::PipelineViewportStateCreateInfo viewport({}, 1, nullptr, 1, nullptr);
  // Surfaces may be open or inside out: nothing is culled. Under a
  // wireframe the surface sits a little deeper, so its lines win the depth test.
  const vk::PipelineRasterizationStateCreateInfo raster(
      {}, false, false, lines ? vk::PolygonMode::eLine : vk::PolygonMode::eFill, vk::CullModeFlagBits::eNone,
      vk::FrontFace::eCounterClockwise, biased, biased ? 1.0f : 0.0f, 0.0f, biased ? 1.0f : 0.0f, 1.0f);
  const vk::PipelineMultisampleStateCreateInfo multisample({}, samples);
  const vk::PipelineDepthStencilStateCreateInfo depth({}, true, true, vk::CompareOp::eLessOrEqual);
  const vk::PipelineColorBlendAttachmentState blend(false, {}, {}, {}, {}, {}, {},
                                                    vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                                                        vk::ColorComponentFlagBits::eB |
                                                        vk::ColorComponentFlagBits::eA);
  const vk::PipelineColorBlendStateCreateInfo blending({}, false, vk::LogicOp::eCopy, blend);
  const std::array<vk::DynamicState, 2> dynamic = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
  const vk::PipelineDynamicStateCreateInfo dynamicState({}, dynamic);
  const vk::GraphicsPipelineCreateInfo info({}, stages, &vertexInput, &assembly, nullptr, &viewport, &raster,
                                            &multisample, &depth, &blending, &dynamicState, *layout, *pass, 0);
  context.requireRoomToCompile();
  return vk::raii::Pipeline(device, context.pipelineCache(), info);
}

}  // namespace

int samplesPerPixel(const gpu::GpuContext& context) { return int(multisampling(context.limits())); }

Image drawSurfaces(gpu::GpuContext& context, const Picture& picture, const Layout& layout)
{
  context.requireDrawing();  // before anything is allocated for the picture
  const vk::PhysicalDeviceLimits& limits = context.limits();
  const uint32_t w = uint32_t(picture.width), h = uint32_t(picture.height);
  if (w > limits.maxFramebufferWidth || h > limits.maxFramebufferHeight || w > limits.maxImageDimension2D ||
      h > limits.maxImageDimension2D)
    throw DeviceError("a picture of " + std::to_string(w) + "x" + std::to_string(h) +
                      " is larger than the Vulkan device draws (" +
                      std::to_string(std::min(limits.maxFramebufferWidth, limits.maxImageDimension2D)) + "x" +
                      std::to_string(std::min(limits.maxFramebufferHeight, limits.maxImageDimension2D)) +
                      "); use a smaller " + nameOf(Parameter::Size));
  if (picture.wireframe && !context.canDrawLines())
    throw DeviceError("the Vulkan device " + context.description().name +
                      " cannot draw lines (fillModeNonSolid), so no " + nameOf(Parameter::Wireframe));

  // The vertices are one allocation: refused, before anything is
  // allocated, where the device cannot make it.
  const uint64_t vertexBytes = uint64_t(cornerCount(picture)) * RENDER_VERTEX_FLOATS * sizeof(float);
  const uint64_t allocationLimit = context.description().maxAllocationBytes;
  if (allocationLimit > 0 && vertexBytes > allocationLimit)
    throw DeviceError("the picture's " + std::to_string(cornerCount(picture) / 3) + " triangles need " +
                      std::to_string(vertexBytes >> 20) +
                      " MiB of vertices, more than the Vulkan device allocates at once (" +
                      std::to_string(allocationLimit >> 20) + " MiB); draw fewer or smaller meshes in one picture");

  const vk::raii::Device& device = context.device();
  const vk::SampleCountFlagBits samples = multisampling(limits);
  const vk::Format depth = depthFormat(context.physicalDevice());
  const vk::Extent2D extent(w, h);
  const bool resolve = samples != vk::SampleCountFlagBits::e1;
  using Usage = vk::ImageUsageFlagBits;
  gpu::GpuImage colour(context, kColourFormat, extent, samples,
                       resolve ? Usage::eColorAttachment : Usage::eColorAttachment | Usage::eTransferSrc,
                       vk::ImageAspectFlagBits::eColor);
  gpu::GpuImage depthImage(context, depth, extent, samples, Usage::eDepthStencilAttachment,
                           vk::ImageAspectFlagBits::eDepth);
  std::optional<gpu::GpuImage> resolved;
  if (resolve)
    resolved.emplace(context, kColourFormat, extent, vk::SampleCountFlagBits::e1,
                     Usage::eColorAttachment | Usage::eTransferSrc, vk::ImageAspectFlagBits::eColor);
  const vk::Image result = resolve ? resolved->handle() : colour.handle();

  Stopwatch pipelinesWatch;
  const vk::raii::RenderPass pass = makeRenderPass(device, samples, depth);
  std::vector<vk::ImageView> views = {colour.view(), depthImage.view()};
  if (resolve) views.push_back(resolved->view());
  const vk::raii::Framebuffer framebuffer(device, vk::FramebufferCreateInfo({}, *pass, views, w, h, 1));
  const vk::PushConstantRange push(vk::ShaderStageFlagBits::eVertex, 0, RENDER_PUSH_BYTES);
  const vk::raii::PipelineLayout pipelineLayout(device, vk::PipelineLayoutCreateInfo({}, {}, push));
  const vk::raii::Pipeline surfaces = makePipeline(context, pipelineLayout, pass, samples, false, picture.wireframe);
  std::optional<vk::raii::Pipeline> wires;
  if (picture.wireframe) wires.emplace(makePipeline(context, pipelineLayout, pass, samples, true, false));

  const double pipelinesMs = pipelinesWatch.ms();
  Stopwatch verticesWatch;
  const Framing framing = frame(picture, layout.meshCells.at(0));
  const gpu::GpuBuffer vertices(context,
                                std::max<size_t>(cornerCount(picture) * RENDER_VERTEX_FLOATS * sizeof(float), 4),
                                vk::BufferUsageFlagBits::eVertexBuffer, gpu::MemoryUse::Upload);
  const std::vector<Draw> draws = gather(picture, framing, reinterpret_cast<float*>(vertices.mapped()));
  gpu::GpuBuffer readback(context, vk::DeviceSize(w) * h * 4, vk::BufferUsageFlagBits::eTransferDst,
                          gpu::MemoryUse::Readback);

  const double verticesMs = verticesWatch.ms();
  Stopwatch deviceWatch;
  struct Push {
    glm::mat4 clipFromCentred, viewFromCentred;
  } constants{framing.clipFromCentred, framing.viewFromCentred};
  static_assert(sizeof(Push) == RENDER_PUSH_BYTES);

  context.drawAndWait([&](vk::CommandBuffer cmd) {
    const std::array<vk::ClearValue, 3> clear = {
        vk::ClearColorValue(std::array<float, 4>{RENDER_BACKGROUND_RGB, 1.0f}), vk::ClearDepthStencilValue(1.0f, 0),
        vk::ClearColorValue(std::array<float, 4>{RENDER_BACKGROUND_RGB, 1.0f})};
    cmd.beginRenderPass(
        vk::RenderPassBeginInfo(*pass, *framebuffer, vk::Rect2D({0, 0}, extent),
                                vk::ArrayProxyNoTemporaries<const vk::ClearValue>(resolve ? 3 : 2, clear.data())),
        vk::SubpassContents::eInline);
    cmd.pushConstants(*pipelineLayout, vk::ShaderStageFlagBits::eVertex, 0, sizeof(Push), &constants);
    cmd.bindVertexBuffers(0, vertices.handle(), vk::DeviceSize(0));
    const auto drawAll = [&](const vk::raii::Pipeline& pipeline) {
      cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline);
      for (const Draw& d : draws) {
        const Rect& c = layout.meshCells[d.cell];
        cmd.setViewport(0, vk::Viewport(float(c.x), float(c.y), float(c.width), float(c.height), 0.0f, 1.0f));
        cmd.setScissor(0, vk::Rect2D({c.x, c.y}, {uint32_t(c.width), uint32_t(c.height)}));
        cmd.draw(d.vertexCount, 1, d.firstVertex, 0);
      }
    };
    drawAll(surfaces);
    if (wires) drawAll(*wires);
    cmd.endRenderPass();
    cmd.copyImageToBuffer(
        result, vk::ImageLayout::eTransferSrcOptimal, readback.handle(),
        vk::BufferImageCopy(0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1), {0, 0, 0},
                            vk::Extent3D(extent, 1)));
    const vk::BufferMemoryBarrier toHost(vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eHostRead,
                                         VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, readback.handle(), 0,
                                         VK_WHOLE_SIZE);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eHost, {}, {}, toHost, {});
  });

  log::verbose("draw: pipelines " + std::to_string(int(pipelinesMs)) + " ms, vertices " +
               std::to_string(int(verticesMs)) + " ms, drawing and reading back " +
               std::to_string(int(deviceWatch.ms())) + " ms (" + std::to_string(int(samples)) + " samples per pixel)");
  Image image(picture.width, picture.height);
  std::memcpy(image.rgba.data(), readback.mapped(), image.rgba.size());
  return image;
}

}  // namespace lbmshape::render
