// A Vulkan context for tests: validation on, and every validation message a test failure.
#pragma once

#include <memory>

#include <gtest/gtest.h>

#include "vk/context.hpp"

namespace facet::test {

inline std::unique_ptr<vk::Context> make_validated_context() {
  vk::ContextOptions options;
  options.validation = true;
  auto context = std::make_unique<vk::Context>(options);
  context->set_validation_handler([](const std::string& message) { ADD_FAILURE() << message; });
  return context;
}

}  // namespace facet::test
