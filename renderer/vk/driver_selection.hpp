// Which Vulkan drivers the loader loads. facet's default device is lavapipe (a vk::Context with no
// device named), yet the loader loads and probes every installed driver to list devices that are then
// discarded: on a Debian 12 host with mesa-vulkan-drivers, three more drivers and their libraries, about
// a third of a small frame's start-up (docs/render_speed.md, "Loading one driver").
#pragma once

namespace facet::vk {

// Asks the loader for lavapipe's driver alone (VK_DRIVER_FILES naming its manifests), unless the user
// steers the loader's drivers through its environment or no lavapipe manifest is installed where the
// loader looks.
// A command calls it when it will create contexts without naming a device; it changes the environment,
// so only before any thread starts.
void select_lavapipe_driver_only();

// Whether select_lavapipe_driver_only did; select_every_driver undoes it (vk::Context does when the
// selection gives no device, before it asks again for every driver).
bool lavapipe_driver_selected();
void select_every_driver();

}  // namespace facet::vk
