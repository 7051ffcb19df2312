// text{"csgray", size=, font=, halign=, valign=, spacing=, direction=,
// language=, script=} (docs/script.md, "Text"): OpenSCAD's text() as a
// region whose letters keep the font's curves. Fonts are named, as
// fontconfig knows them; a script cannot name a font file.
#include <stdexcept>
#include <string>

#include "profile/glyph_outlines.h"
#include "script/api.h"
#include "script/lua_args.h"
#include "script/lua_values.h"

namespace csgray::detail {

namespace {

// The value of the option the word `given` names, or an error that lists them.
template <class T>
T choice(const std::optional<std::string>& given, const char* key,
         std::initializer_list<std::pair<const char*, T>> options, T fallback) {
  if (!given) return fallback;
  std::string list;
  for (const auto& [name, value] : options) {
    if (*given == name) return value;
    list += std::string(list.empty() ? "" : ", ") + "\"" + name + "\"";
  }
  throw std::invalid_argument(std::string("text: ") + key + " must be one of " + list + " (got \"" +
                              shortened(*given) + "\")");
}

int text(lua_State* L) {
  checkArgumentCount(L, "text", 1);
  // text("csgray") and text{"csgray", ...} stand for text{text="csgray", ...}.
  if (lua_type(L, 1) == LUA_TSTRING) {
    lua_createtable(L, 0, 1);
    lua_pushvalue(L, 1);
    lua_setfield(L, -2, "text");
    lua_replace(L, 1);
  } else if (lua_type(L, 1) == LUA_TTABLE) {
    if (lua_rawgeti(L, 1, 1) != LUA_TNIL) {
      lua_setfield(L, 1, "text");
      lua_pushnil(L);
      lua_rawseti(L, 1, 1);
    } else {
      lua_pop(L, 1);
    }
  } else {
    throw std::invalid_argument(std::string("text: needs a string, got ") + shownType(L, 1));
  }
  LuaArgs args(L, 1, "text");
  TextLayout layout;
  const std::optional<std::string> string = args.string("text");
  if (!string) throw std::invalid_argument("text: needs the string to write: text{\"csgray\"}");
  layout.text = *string;
  if (auto v = args.number("size")) layout.size = *v;
  if (auto v = args.string("font")) layout.font = *v;
  if (auto v = args.number("spacing")) layout.spacing = *v;
  using H = TextLayout::HAlign;
  using V = TextLayout::VAlign;
  using D = TextLayout::Direction;
  layout.halign =
      choice<H>(args.string("halign"), "halign",
                {{"left", H::Left}, {"center", H::Center}, {"right", H::Right}}, H::Left);
  layout.valign = choice<V>(
      args.string("valign"), "valign",
      {{"baseline", V::Baseline}, {"bottom", V::Bottom}, {"center", V::Center}, {"top", V::Top}},
      V::Baseline);
  layout.direction = choice<D>(args.string("direction"), "direction",
                               {{"ltr", D::LeftToRight},
                                {"rtl", D::RightToLeft},
                                {"ttb", D::TopToBottom},
                                {"btt", D::BottomToTop}},
                               D::LeftToRight);
  if (auto v = args.string("language")) layout.language = *v;
  if (auto v = args.string("script")) layout.script = *v;
  args.finish();
  pushRegion(L, textRegion(layout), "text");
  return 1;
}

}  // namespace

void registerTextApi(lua_State* L) { lua_register(L, "text", guarded<text>); }

}  // namespace csgray::detail
