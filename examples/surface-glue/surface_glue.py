#!/usr/bin/env python3
"""Writes a host's glue for weathergen surfaces from their reflection alone.

A foreign host's view of the surface contract (docs/engine-api.md, "The surface
contract"): it reads only NAME.reflect.json's "surface" object, never the shader text,
and writes a vertex and a fragment shader that include one or more surfaces, call
their functions and write the results to a G-buffer, with its own camera block.

Usage: surface_glue.py LANGUAGE OUT_DIR REFLECT_JSON... [--define MACRO=VALUE]...
  LANGUAGE: glsl, glsles or hlsl. Writes OUT_DIR/glue.vert and OUT_DIR/glue.frag
  (.vert.hlsl / .frag.hlsl for HLSL), each with the surfaces' text pasted in, as a
  host with no #include support would.
"""
import argparse
import json
import sys
from pathlib import Path

HLSL_TYPES = {"float": "float", "vec2": "float2", "vec3": "float3", "vec4": "float4", "bool": "bool", "uint": "uint"}
# What this host hands every surface: its own vertex attributes, in world space.
HOST_VERTEX = {
    "worldPosition": "in_position",
    "worldNormal": "in_normal",
    "worldTangent": "in_tangent",
    "texcoord": "in_texcoord",
    "texcoord1": "in_texcoord",
    "color": "vec4(1.0)",
    "cameraPosition": "host_eye",
}
HOST_ATTRIBUTES = [("in_position", "vec3"), ("in_normal", "vec3"), ("in_tangent", "vec4"), ("in_texcoord", "vec2")]
# The G-buffer: what a deferred host keeps of each surface.
GBUFFER = [
    ("gbuffer_albedo", "vec4(o.baseColor, o.opacity)"),
    ("gbuffer_normal", "vec4(o.normal * 0.5 + 0.5, o.roughness)"),
    ("gbuffer_material", "vec4(o.metallic, o.specular, o.occlusion, o.snow)"),
    ("gbuffer_emissive", "vec4(o.emissive, o.wet)"),
]


def load(paths):
    surfaces = []
    for path in paths:
        reflection = json.loads(Path(path).read_text())
        surface = reflection["surface"]
        surface["folder"] = Path(path).parent
        surfaces.append(surface)
    return surfaces


def type_name(language, glsl_type):
    return HLSL_TYPES[glsl_type] if language == "hlsl" else glsl_type


def varyings(surfaces):
    """Every surface's vertex output, each field its own varying: (surface, field, type)."""
    out = []
    for s in surfaces:
        for field in s["structs"][s["vertex"]["output"]]:
            out.append((s, field["name"], field["type"]))
    return out


def host_resources(language, surfaces):
    """Every resource the surfaces read, declared by the host in its own set 4 (a
    host whose resources are its own: WG_HOST_DECLARES_RESOURCES)."""
    lines, seen = [f"#define {surfaces[0]['hostResourcesMacro']}"], set()
    resources = [r for s in surfaces for r in s["resources"]]
    for binding, r in enumerate(resources):
        if r["identifier"] in seen:
            continue
        seen.add(r["identifier"])
        if r["kind"] == "uniformBlock":
            members = "".join(f"  {type_name(language, m['type'])} {m['identifier']};\n" for m in r["members"])
            if language == "hlsl":
                lines.append(f"[[vk::binding({binding}, 4)]] cbuffer Host{r['identifier']} : register(b{binding}, space4) "
                             f"{{\n{members}}};")
            else:
                layout = f"std140, binding = {binding}" if language == "glsles" else f"set = 4, binding = {binding}, std140"
                lines.append(f"layout({layout}) uniform Host{r['identifier']} {{\n{members}}};")
        elif language == "hlsl":
            kind, register = ("Texture2D", "t") if r["kind"] == "texture" else ("SamplerState", "s")
            lines.append(f"[[vk::binding({binding}, 4)]] {kind} {r['identifier']} : register({register}{binding}, space4);")
        elif language == "glsles":
            if r["kind"] == "texture":  # combined: the texture is the sampler2D
                lines.append(f"layout(binding = {binding}) uniform highp sampler2D {r['identifier']};")
        else:
            kind = "texture2D" if r["kind"] == "texture" else "sampler"
            lines.append(f"layout(set = 4, binding = {binding}) uniform {kind} {r['identifier']};")
    return lines


def preamble(language, stage, surfaces, defines, own_resources=False):
    lines = []
    if language == "glsl":
        lines.append("#version 440")  # the lowest the contract promises (docs/engine-api.md)
    elif language == "glsles":
        lines += ["#version 310 es", "precision highp float;", "precision highp int;"]
    lines.append(f"#define {surfaces[0]['stageMacros'][stage]}")
    lines += [f"#define {name} {value}" for name, value in defines]
    if own_resources:
        lines += host_resources(language, surfaces)
    for s in surfaces:
        lines.append(Path(s["folder"], s["files"][language]).read_text())
    return "\n".join(lines) + "\n"


def host_block(language):
    if language == "hlsl":
        return ("[[vk::binding(0, 7)]] cbuffer HostCamera : register(b0, space7) {\n"
                "  float4x4 host_viewProjection;\n  float3 host_eye;\n};\n")
    layout = "layout(std140, binding = 15)" if language == "glsles" else "layout(set = 7, binding = 0, std140)"
    return f"{layout} uniform HostCamera {{\n  mat4 host_viewProjection;\n  vec3 host_eye;\n}};\n"


def vertex_glsl(language, surfaces, defines, own_resources=False):
    text = preamble(language, "vertex", surfaces, defines, own_resources) + host_block(language)
    for location, (name, glsl_type) in enumerate(HOST_ATTRIBUTES):
        text += f"layout(location = {location}) in {glsl_type} {name};\n"
    for location, (s, field, glsl_type) in enumerate(varyings(surfaces)):
        text += f"layout(location = {location}) out {glsl_type} v_{s['prefix']}{field};\n"
    text += "void main() {\n  vec3 position = vec3(0.0);\n"
    for s in surfaces:
        vin, vout, p = s["vertex"]["input"], s["vertex"]["output"], s["prefix"]
        text += f"  {vin} {p}in;\n"
        for field in s["structs"][vin]:
            text += f"  {p}in.{field['name']} = {HOST_VERTEX[field['name']]};\n"
        text += f"  {vout} {p}out = {s['vertex']['function']}({p}in);\n"
        for field in s["structs"][vout]:
            text += f"  v_{p}{field['name']} = {p}out.{field['name']};\n"
        text += f"  position += {p}out.worldPosition;\n"
    text += f"  gl_Position = host_viewProjection * vec4(position / {float(len(surfaces))}, 1.0);\n}}\n"
    return text


def fragment_glsl(language, surfaces, defines, own_resources=False):
    text = preamble(language, "fragment", surfaces, defines, own_resources) + host_block(language)
    for location, (s, field, glsl_type) in enumerate(varyings(surfaces)):
        text += f"layout(location = {location}) in {glsl_type} v_{s['prefix']}{field};\n"
    for location, (name, _) in enumerate(GBUFFER):
        text += f"layout(location = {location}) out vec4 {name};\n"
    text += "void main() {\n"
    text += "".join(f"  {name} = vec4(0.0);\n" for name, _ in GBUFFER)
    for s in surfaces:
        fin, fout, p = s["fragment"]["input"], s["fragment"]["output"], s["prefix"]
        text += f"  {fin} {p}in;\n"
        vertex_fields = {f["name"] for f in s["structs"][s["vertex"]["output"]]}
        for field in s["structs"][fin]:
            name = field["name"]
            value = (f"v_{p}{name}" if name in vertex_fields else
                     "gl_FrontFacing" if name == "frontFacing" else "host_eye")
            text += f"  {p}in.{name} = {value};\n"
        text += f"  {{\n    {fout} o = {s['fragment']['function']}({p}in);\n"
        text += "".join(f"    {name} += {value};\n" for name, value in GBUFFER)
        text += "  }\n"
    text += "}\n"
    return text


def vertex_hlsl(surfaces, defines, own_resources=False):
    text = preamble("hlsl", "vertex", surfaces, defines, own_resources) + host_block("hlsl")
    text += "struct HostVertex {\n"
    for location, (name, glsl_type) in enumerate(HOST_ATTRIBUTES):
        text += f"  [[vk::location({location})]] {HLSL_TYPES[glsl_type]} {name} : TEXCOORD{location};\n"
    text += "};\nstruct HostVaryings {\n  float4 position : SV_Position;\n"
    for location, (s, field, glsl_type) in enumerate(varyings(surfaces)):
        text += f"  [[vk::location({location})]] {HLSL_TYPES[glsl_type]} {s['prefix']}{field} : TEXCOORD{location};\n"
    text += "};\nHostVaryings main(HostVertex v) {\n  HostVaryings r;\n  float3 position = (float3)0;\n"
    for s in surfaces:
        vin, vout, p = s["vertex"]["input"], s["vertex"]["output"], s["prefix"]
        text += f"  {vin} {p}in = ({vin})0;\n"
        for field in s["structs"][vin]:
            source = HOST_VERTEX[field["name"]]
            source = "(float4)1.0" if source == "vec4(1.0)" else source if source == "host_eye" else "v." + source
            text += f"  {p}in.{field['name']} = {source};\n"
        text += f"  {vout} {p}out = {s['vertex']['function']}({p}in);\n"
        for field in s["structs"][vout]:
            text += f"  r.{p}{field['name']} = {p}out.{field['name']};\n"
        text += f"  position += {p}out.worldPosition;\n"
    text += f"  r.position = mul(host_viewProjection, float4(position / {float(len(surfaces))}, 1.0));\n  return r;\n}}\n"
    return text


def fragment_hlsl(surfaces, defines, own_resources=False):
    text = preamble("hlsl", "fragment", surfaces, defines, own_resources) + host_block("hlsl")
    text += "struct HostVaryings {\n"
    for location, (s, field, glsl_type) in enumerate(varyings(surfaces)):
        text += f"  [[vk::location({location})]] {HLSL_TYPES[glsl_type]} {s['prefix']}{field} : TEXCOORD{location};\n"
    text += "};\nstruct GBuffer {\n"
    text += "".join(f"  float4 {name} : SV_Target{i};\n" for i, (name, _) in enumerate(GBUFFER))
    text += "};\nGBuffer main(HostVaryings v, bool frontFacing : SV_IsFrontFace) {\n  GBuffer g = (GBuffer)0;\n"
    for s in surfaces:
        fin, fout, p = s["fragment"]["input"], s["fragment"]["output"], s["prefix"]
        text += f"  {fin} {p}in = ({fin})0;\n"
        vertex_fields = {f["name"] for f in s["structs"][s["vertex"]["output"]]}
        for field in s["structs"][fin]:
            name = field["name"]
            value = f"v.{p}{name}" if name in vertex_fields else "frontFacing" if name == "frontFacing" else "host_eye"
            text += f"  {p}in.{name} = {value};\n"
        text += f"  {{\n    {fout} o = {s['fragment']['function']}({p}in);\n"
        for name, value in GBUFFER:
            value = value.replace("vec4(", "float4(")
            text += f"    g.{name} += {value};\n"
        text += "  }\n"
    text += "  return g;\n}\n"
    return text


def write_glue(language, out_dir, reflections, defines=(), host_resources=False):
    """Writes the glue; returns (vertex path, fragment path). host_resources: the glue
    declares every resource itself instead of the surfaces."""
    surfaces = load(reflections)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    if language == "hlsl":
        vertex, fragment = out / "glue.vert.hlsl", out / "glue.frag.hlsl"
        vertex.write_text(vertex_hlsl(surfaces, defines, host_resources))
        fragment.write_text(fragment_hlsl(surfaces, defines, host_resources))
    else:
        vertex, fragment = out / "glue.vert", out / "glue.frag"
        vertex.write_text(vertex_glsl(language, surfaces, defines, host_resources))
        fragment.write_text(fragment_glsl(language, surfaces, defines, host_resources))
    return vertex, fragment


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("language", choices=["glsl", "glsles", "hlsl"])
    parser.add_argument("out_dir")
    parser.add_argument("reflections", nargs="+")
    parser.add_argument("--define", action="append", default=[], metavar="MACRO=VALUE")
    parser.add_argument("--host-resources", action="store_true", help="declare every resource in the glue")
    args = parser.parse_args(argv)
    defines = [tuple(d.split("=", 1)) if "=" in d else (d, "") for d in args.define]
    for path in write_glue(args.language, args.out_dir, args.reflections, defines, args.host_resources):
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
