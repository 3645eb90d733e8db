#pragma once
// What the scene's YAML text and its sections share (SceneYaml.cpp, SceneSection.cpp).

namespace cyclone::scenes {

/// What an empty flow list `[]` becomes before Teuchos reads the text (it has no element
/// type to give an empty array); the list getters read it back as an empty list.
inline const char* const kEmptyList = "__cyclone_empty_list__";

}  // namespace cyclone::scenes
