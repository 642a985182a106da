#!/usr/bin/env python3
"""Regenerates graphs/schema/material-graph.schema.json from the compiler's own tables.

Usage: scripts/generate-schema.py [path/to/weathergen]   (default: build/weathergen)
Ops, their ports and literal ranges come from `weathergen list-ops --json`, so the schema
follows the op registry; tests/unit/schema_sync_test.cpp fails when they drift apart.
"""
import json, os, subprocess, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLI = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, 'build', 'weathergen')
ops = json.loads(subprocess.run([CLI, 'list-ops', '--json'], capture_output=True, text=True, check=True).stdout)
PORT_REF = {'float': 'floatInput', 'vec2': 'vec2Input', 'vec3': 'vec3Input', 'vec4': 'vec4Input',
            'bool': 'boolInput', 'T': 'genericInput', 'texture': 'textureInput', 'text': 'channelsInput'}

def num(lo=None, hi=None, **extra):
    s = {"type": "number"}
    if lo is not None: s["minimum"] = lo
    if hi is not None: s["maximum"] = hi
    s.update(extra)
    return s

def vec(n, lo=None, hi=None):
    return {"type": "array", "items": num(lo, hi), "minItems": n, "maxItems": n}

def outputField(desc, typ, lo=None, hi=None, default=None):
    alts = [{"$ref": "#/$defs/link"}, num(lo, hi, description="a float literal (splatted for vec3 fields)" if typ == 'vec3' else "a literal")]
    if typ == 'vec3':
        alts.append(vec(3, lo, hi))
    s = {"description": desc, "anyOf": alts}
    if default is not None: s["default"] = default
    return s

generators = {
    "fbm": {
        "description": "periodic value-noise fBm: rgb = mix(colorA, colorB, noise), alpha = noise (height/mask)",
        "options": {
            "scale": {"type": "integer", "minimum": 1, "maximum": 64, "default": 8, "description": "lattice cells across the tile (larger: finer features)"},
            "octaves": {"type": "integer", "minimum": 1, "maximum": 8, "default": 5, "description": "noise layers, each at twice the previous frequency"},
            "gain": num(0, 1, default=0.5, description="amplitude of each octave relative to the previous one (larger: rougher)"),
            "colorA": {"$ref": "#/$defs/color3", "default": [0.2, 0.2, 0.2], "description": "colour where the noise is 0"},
            "colorB": {"$ref": "#/$defs/color3", "default": [0.8, 0.8, 0.8], "description": "colour where the noise is 1"},
        }},
    "fbm_normal": {
        "description": "tangent-space normal map of the fbm height (x along +u, y along +v): rgb = normal*0.5+0.5, alpha = height",
        "options": {
            "scale": {"type": "integer", "minimum": 1, "maximum": 64, "default": 8, "description": "lattice cells across the tile (larger: finer features)"},
            "octaves": {"type": "integer", "minimum": 1, "maximum": 8, "default": 5, "description": "noise layers, each at twice the previous frequency"},
            "gain": num(0, 1, default=0.5, description="amplitude of each octave relative to the previous one (larger: rougher)"),
            "strength": num(0, 16, default=2, description="bump height: slope multiplier (0: flat)"),
        }},
    "voronoi": {
        "description": "periodic cellular noise: rgb = per-cell mix(colorA, colorB) darkened in the cracks, alpha = crack mask, 1 on cell borders",
        "options": {
            "scale": {"type": "integer", "minimum": 1, "maximum": 64, "default": 8, "description": "lattice cells across the tile (larger: finer features)"},
            "colorA": {"$ref": "#/$defs/color3", "default": [0.3, 0.3, 0.3], "description": "colour of cells with random value 0"},
            "colorB": {"$ref": "#/$defs/color3", "default": [0.6, 0.6, 0.6], "description": "colour of cells with random value 1"},
            "edgeWidth": num(0, 1, default=0.1, description="crack width across the border, in cells (F2-F1 scale; 0: no cracks)"),
        }},
    "flow": {
        "description": "smooth flow noise for wind panning: r, g = two decorrelated fbm fields, b = their average, alpha = 1",
        "options": {
            "scale": {"type": "integer", "minimum": 1, "maximum": 64, "default": 4, "description": "lattice cells across the tile (larger: finer features)"},
            "octaves": {"type": "integer", "minimum": 1, "maximum": 8, "default": 3, "description": "noise layers, each at twice the previous frequency"},
        }},
}

defs = {}
defs["link"] = {"description": "a link to a node output: \"nodeId.output\" (the id is everything before the last dot)",
                "type": "string", "pattern": "^.+\\.[A-Za-z0-9_]+$"}
defs["color3"] = vec(3, 0, 1)
defs["wrapMode"] = {"enum": ["repeat", "clamp", "mirror"]}
defs["wrap"] = {"description": "addressing outside [0, 1]: one mode for both axes, or [u, v]",
                "anyOf": [{"$ref": "#/$defs/wrapMode"},
                          {"type": "array", "items": {"$ref": "#/$defs/wrapMode"}, "minItems": 2, "maxItems": 2}],
                "default": "repeat"}
defs["filterMode"] = {"enum": ["linear", "nearest"]}
defs["filter"] = {"description": "texel filtering: one filter for both directions, or {min, mag} (a direction left out is linear)",
                  "anyOf": [{"$ref": "#/$defs/filterMode"},
                            {"type": "object", "additionalProperties": False,
                             "properties": {"min": {"$ref": "#/$defs/filterMode", "description": "minification"},
                                            "mag": {"$ref": "#/$defs/filterMode", "description": "magnification"}}}],
                  "default": "linear"}
defs["colorSpace"] = {"description": "srgb: colour is sRGB-encoded and decoded to linear before filtering (alpha stays linear)",
                      "enum": ["linear", "srgb"], "default": "linear"}
defs["inputValue"] = {
    "description": "a link \"nodeId.output\", a texture name (op sample), swizzle channels (op swizzle), or a literal",
    "anyOf": [{"type": "string"}, {"type": "number"}, {"type": "boolean"},
              {"type": "array", "items": {"type": "number"}, "minItems": 2, "maxItems": 4}]}
defs["floatInput"] = {"anyOf": [{"$ref": "#/$defs/link"}, num()]}
for n in (2, 3, 4):
    defs[f"vec{n}Input"] = {"description": f"vec{n}: a link, a {n}-number array, or a number (splatted to every component)",
                            "anyOf": [{"$ref": "#/$defs/link"}, num(), vec(n)]}
defs["boolInput"] = {"anyOf": [{"$ref": "#/$defs/link"}, {"type": "boolean"}]}
defs["genericInput"] = {"description": "T (float, vec2, vec3 or vec4, one width per node; a float splats)",
                        "anyOf": [{"$ref": "#/$defs/link"}, num(),
                                  {"type": "array", "items": num(), "minItems": 2, "maxItems": 4}]}
defs["textureInput"] = {"description": "the name of a texture declared under \"textures\"", "type": "string"}
defs["channelsInput"] = {"description": "1 to 4 components, all from xyzw or all from rgba, e.g. \"xz\" or \"rgb\"",
                         "type": "string", "pattern": "^([xyzw]{1,4}|[rgba]{1,4})$"}

defs["parameter"] = {
    "description": "a material parameter: a member mat_<name> of the std140 material uniform block",
    "type": "object",
    "required": ["type", "default"],
    "additionalProperties": False,
    "properties": {
        "type": {"enum": ["float", "vec2", "vec3", "vec4", "bool"]},
        "default": {"description": "initial value, of the parameter's type and inside [min, max]"},
        "min": {"type": "number", "description": "lower bound for tools and for the default (per component)"},
        "max": {"type": "number", "description": "upper bound for tools and for the default (per component)"},
        "label": {"type": "string", "description": "name shown to artists"},
        "description": {"type": "string"},
    },
    "allOf": [
        {"if": {"properties": {"type": {"const": "float"}}}, "then": {"properties": {"default": {"type": "number"}}}},
        {"if": {"properties": {"type": {"const": "vec2"}}}, "then": {"properties": {"default": vec(2)}}},
        {"if": {"properties": {"type": {"const": "vec3"}}}, "then": {"properties": {"default": vec(3)}}},
        {"if": {"properties": {"type": {"const": "vec4"}}}, "then": {"properties": {"default": vec(4)}}},
        {"if": {"properties": {"type": {"const": "bool"}}}, "then": {"properties": {"default": {"type": "boolean"}}}},
    ],
}

defs["fileTexture"] = {
    "description": "an image file (PNG or JPEG, at most 8192x8192), relative to the graph file",
    "type": "object", "required": ["file"], "additionalProperties": False,
    "properties": {"file": {"type": "string"}, "wrap": {"$ref": "#/$defs/wrap"},
                   "filter": {"$ref": "#/$defs/filter"}, "colorSpace": {"$ref": "#/$defs/colorSpace"},
                   "description": {"type": "string"}},
}
common = {
    "generator": None,
    "seed": {"type": "integer", "minimum": 0, "maximum": 4294967295, "default": 0,
             "description": "random seed (write a whole number without a decimal point)"},
    "size": {"enum": [16, 32, 64, 128, 256, 512, 1024, 2048], "default": 256,
             "description": "width and height in texels"},
    "wrap": {"$ref": "#/$defs/wrap"}, "filter": {"$ref": "#/$defs/filter"},
    "colorSpace": {"const": "linear", "description": "generators make linear values; srgb is for image files"},
    "description": {"type": "string"},
}
branches = []
for name, g in generators.items():
    props = dict(common)
    props["generator"] = {"const": name}
    props.update(g["options"])
    defs[f"{name}Texture"] = {"description": g["description"], "type": "object", "required": ["generator"],
                              "additionalProperties": False, "properties": props}
    branches.append({"if": {"properties": {"generator": {"const": name}}}, "then": {"$ref": f"#/$defs/{name}Texture"}})
defs["generatorTexture"] = {
    "description": "a procedural texture baked by a built-in generator (see 'weathergen list-generators')",
    "type": "object", "required": ["generator"],
    "properties": {"generator": {"enum": list(generators)}},
    "allOf": branches,
}
defs["texture"] = {"oneOf": [{"$ref": "#/$defs/fileTexture"}, {"$ref": "#/$defs/generatorTexture"}]}

opBranches = []
for op in ops:
    props, required = {}, []
    for port in op["inputs"]:
        s = {"$ref": "#/$defs/" + PORT_REF[port["type"]]}
        rng = (port["min"], port["max"]) if "min" in port else None
        d = f'{port["type"]}' + ("" if port["default"] == "required" else f', default {port["default"]}')
        if rng:
            s = {"anyOf": [{"$ref": "#/$defs/link"}, num(*rng)]}
            d += f", literal in [{rng[0]}, {rng[1]}]"
        s["description"] = d
        props[port["name"]] = s
        if port["default"] == "required": required.append(port["name"])
    inputs = {"type": "object", "properties": props, "additionalProperties": False}
    if required: inputs["required"] = required
    then = {"description": f'{op["name"]} ({op["category"]}): {op["summary"]}; outputs: {op["outputs"]}',
            "properties": {"inputs": inputs}}
    if required: then["required"] = ["inputs"]
    if op["name"] == "parameter":
        then["required"] = ["param"]
    opBranches.append({"if": {"properties": {"op": {"const": op["name"]}}, "required": ["op"]}, "then": then})
opBranches.append({"if": {"not": {"properties": {"op": {"const": "parameter"}}}}, "then": {"not": {"required": ["param"]}}})
# Op "switch" is resolved before typing (compiler/static_switches.cpp), so it is not in
# the op registry: it follows a declared switch and has one case per switch value.
opBranches.append({"if": {"properties": {"op": {"const": "switch"}}, "required": ["op"]},
                   "then": {"description": "switch: the case of the chosen variant's switch value; output: out",
                            "required": ["switch", "cases"], "not": {"required": ["inputs"]}},
                   "else": {"not": {"anyOf": [{"required": ["switch"]}, {"required": ["cases"]}]}}})

defs["node"] = {
    "type": "object", "required": ["id", "op"], "additionalProperties": False,
    "properties": {
        "id": {"type": "string", "minLength": 1, "description": "unique node id; other nodes link to \"id.output\""},
        "op": {"enum": [o["name"] for o in ops] + ["switch"],
               "enumDescriptions": [f'{o["category"]}: {o["summary"]}' for o in ops] +
                                   ["static switch: one case per value of a declared switch"]},
        "inputs": {"type": "object", "additionalProperties": {"$ref": "#/$defs/inputValue"},
                   "description": "port name -> link \"nodeId.output\", literal, texture name or swizzle channels"},
        "param": {"type": "string", "description": "op parameter only: the name of a declared parameter"},
        "switch": {"$ref": "#/$defs/switchWord", "description": "op switch only: the name of a declared switch"},
        "cases": {"type": "object", "propertyNames": {"$ref": "#/$defs/switchWord"},
                  "additionalProperties": {"$ref": "#/$defs/inputValue"},
                  "description": "op switch only: switch value -> link or literal, one for every value"},
        "description": {"type": "string"},
    },
    "allOf": opBranches,
}

schema = {
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "title": "weathergen material graph",
    "description": "A JSON material graph compiled by weathergen to GLSL, HLSL and SPIR-V. See docs/graph-format.md.",
    "type": "object",
    "required": ["name", "nodes", "output"],
    "additionalProperties": False,
    "properties": {
        "$schema": {"type": "string", "description": "this schema, for editor completion (ignored by the compiler)"},
        "name": {"type": "string", "minLength": 1, "description": "material name; output files are NAME.*"},
        "description": {"type": "string"},
        "parameters": {"type": "object", "propertyNames": {"minLength": 1},
                       "additionalProperties": {"$ref": "#/$defs/parameter"}},
        "textures": {"type": "object", "additionalProperties": {"$ref": "#/$defs/texture"}},
        "include": {"type": "object", "propertyNames": {"$ref": "#/$defs/switchWord"},
                    "additionalProperties": {"type": "string", "minLength": 1},
                    "description": "graph libraries: alias -> path relative to this file; their parameters, "
                                   "textures and nodes join the graph as ALIAS.NAME (docs/graph-format.md)"},
        "switches": {"type": "object", "propertyNames": {"$ref": "#/$defs/switchWord"},
                     "additionalProperties": {"$ref": "#/$defs/switch"},
                     "description": "static switches: each permutation is one shader variant (weathergen compile --variants)"},
        "nodes": {"type": "array", "items": {"$ref": "#/$defs/node"}},
        "output": {
            "type": "object", "additionalProperties": False,
            "description": "PBR output fields; each is a link \"nodeId.output\" or a literal; unset fields take their defaults",
            "properties": {
                "baseColor": outputField("vec3, fragment stage: linear albedo", "vec3", 0, 1, [0.5, 0.5, 0.5]),
                "metallic": outputField("float, fragment stage", "float", 0, 1, 0.0),
                "roughness": outputField("float, fragment stage: perceptual roughness (GGX alpha = roughness^2)", "float", 0, 1, 0.5),
                "specular": outputField("float, fragment stage: dielectric F0 = 0.08 * specular (0.5 gives 0.04)", "float", 0, 1, 0.5),
                "normal": outputField("vec3, fragment stage: tangent-space normal", "vec3", -1, 1, [0.0, 0.0, 1.0]),
                "ambientOcclusion": outputField("float, fragment stage", "float", 0, 1, 1.0),
                "emissive": outputField("vec3, fragment stage: emitted radiance (linear, unbounded)", "vec3", 0, None, [0.0, 0.0, 0.0]),
                "opacity": outputField("float, fragment stage: alpha-tested against alphaCutoff (alphaMode mask, the default once set) or blended (alphaMode blend)", "float", 0, 1, 1.0),
                "worldPositionOffset": outputField("vec3, VERTEX stage: world-space offset added to each vertex position (metres)", "vec3", None, None, [0.0, 0.0, 0.0]),
            },
        },
        "weather": {"description": "weather response (docs/weather-model.md): a preset name, or a preset with overrides",
                    "anyOf": [{"$ref": "#/$defs/weatherPreset"}, {"$ref": "#/$defs/weatherBlock"}]},
        "alphaCutoff": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.5,
                        "description": "fragments with opacity below this are discarded (alphaMode mask only)"},
        "alphaMode": {"enum": ["opaque", "mask", "blend"],
                      "enumDescriptions": ["opacity is ignored", "alpha test against alphaCutoff",
                                           "blended over what lies behind (straight alpha), drawn after opaque objects"],
                      "description": "how opacity reaches the image; absent: mask when output.opacity is set, else opaque"},
        "doubleSided": {"type": "boolean", "default": False,
                        "description": "draw back faces too (their normal is flipped); default false culls them"},
    },
    "$defs": defs,
}

defs["switchWord"] = {"type": "string", "pattern": "^[A-Za-z][A-Za-z0-9_-]{0,31}$"}
defs["switch"] = {"oneOf": [
    {"type": "object", "required": ["type", "default"], "additionalProperties": False,
     "description": "a bool switch: values off and on",
     "properties": {"type": {"const": "bool"}, "default": {"type": "boolean"}, "description": {"type": "string"}}},
    {"type": "object", "required": ["values", "default"], "additionalProperties": False,
     "properties": {"values": {"type": "array", "items": {"$ref": "#/$defs/switchWord"}, "minItems": 2, "maxItems": 16,
                               "uniqueItems": True},
                    "default": {"$ref": "#/$defs/switchWord", "description": "one of values"},
                    "description": {"type": "string"}}},
]}
defs["switchedEffect"] = {
    "type": "object", "required": ["switch"], "additionalProperties": False,
    "description": "on when a bool switch is on, or when the switch has one of the values in 'when'",
    "properties": {"switch": {"$ref": "#/$defs/switchWord"},
                   "when": {"type": "array", "items": {"$ref": "#/$defs/switchWord"}}}}
defs["weatherPreset"] = {"enum": ["rock", "terrain", "foliage", "river", "road", "none"],
                         "description": "seed 000 chapter 5: rock (full prediction, displacement, terrain, moss, wetness), "
                                        "terrain (detail, height, wind), foliage (detail mask, density), river (frost then ice), "
                                        "road (wetness, puddles, frost), none"}
effectNames = ["snow", "displacement", "terrainOrientation", "moss", "wetness", "puddles", "ice", "hoarfrost",
               "foliageDensity", "skyExposure", "relief", "ripple", "specularAntiAliasing"]
defs["weatherBlock"] = {
    "type": "object", "required": ["preset"], "additionalProperties": False,
    "properties": {
        "preset": {"$ref": "#/$defs/weatherPreset"},
        "description": {"type": "string"},
        "quality": {"enum": ["low", "medium", "high"],
                    "description": "quality tier (docs/weather-model.md, Quality tiers): low = seed 000's terms, medium = "
                                   "plus sky exposure, high = plus the looks; the CLI's --quality overrides it"},
        "effects": {"type": "object", "additionalProperties": False, "description": "switch a preset's effects on or off",
                    "properties": {e: {"anyOf": [{"type": "boolean"}, {"$ref": "#/$defs/switchedEffect"}]}
                                       for e in effectNames}},
        "weights": {"type": "array", "items": num(0, 16), "minItems": 4, "maxItems": 4,
                    "description": "eq. 3.1 weights [w1 sun, w2 wind, w3 height, w4 terrain]; become parameters weather.w1-w4"},
        "terms": {"type": "array", "items": {"enum": [0, 1]}, "minItems": 4, "maxItems": 4,
                  "description": "eq. 3.1 factors used: [inclination, sun, height, wind]"},
        "steep": {"type": "object", "required": ["preset"], "additionalProperties": False,
                  "description": "a second preset for the steep parts, blended in by slope (seed 000, 5.1.1: a terrain's "
                                 "cliffs take rock's complete prediction); the two may differ only in moss and terrainOrientation",
                  "properties": {"preset": {"$ref": "#/$defs/weatherPreset"},
                                 "slope": {"type": "array", "items": num(0, 90), "minItems": 2, "maxItems": 2,
                                           "description": "[FROM, TO] degrees from level: all flat below FROM, all steep "
                                                          "above TO; default [30, 45]"},
                                 "description": {"type": "string"}}},
        "maxSnowHeight": num(0, 10, description="metres (eq. 3.10); default 0.25"),
        "minHeight": num(-1e5, 1e5, description="metres (eq. 3.8)"),
        "maxHeight": num(-1e5, 1e5, description="metres (eq. 3.8)"),
        "inclinationIntensity": num(0, 4, description="eq. 3.4 normal-map term"),
        "terrainSlopeIntensity": num(-1000, 1000, description="eq. 3.12"),
        "terrainIntensity": num(-16, 16, description="eq. 3.13"),
        "foliageThinning": num(0, 1, description="share of foliage removed under full snow"),
    },
}

def fmt(o, depth=0, col=0):
    one = json.dumps(o, ensure_ascii=False)
    if col + len(one) <= 110 or not isinstance(o, (dict, list)) or not o:
        return one
    pad = "  " * (depth + 1)
    end = "  " * depth
    if isinstance(o, dict):
        items = []
        for k, v in o.items():
            head = f"{pad}{json.dumps(k)}: "
            items.append(head + fmt(v, depth + 1, len(head)))
        return "{\n" + ",\n".join(items) + "\n" + end + "}"
    items = [pad + fmt(v, depth + 1, len(pad)) for v in o]
    return "[\n" + ",\n".join(items) + "\n" + end + "]"

open(os.path.join(ROOT, 'graphs', 'schema', 'material-graph.schema.json'), 'w').write(fmt(schema) + "\n")

# A graph library: what a graph includes. Same parameters, textures and nodes; no name,
# output, weather or switches of its own, and no includes.
library = {
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "title": "weathergen graph library",
    "description": "Parameters, textures and nodes that material graphs include as ALIAS.NAME. See docs/graph-format.md.",
    "type": "object",
    "required": ["nodes"],
    "additionalProperties": False,
    "properties": {key: schema["properties"][key] for key in ["$schema", "description", "parameters", "textures", "nodes"]},
    "$defs": defs,
}
open(os.path.join(ROOT, 'graphs', 'schema', 'graph-library.schema.json'), 'w').write(fmt(library) + "\n")
