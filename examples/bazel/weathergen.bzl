"""weathergen_materials: one cacheable Bazel action per material graph.

Each graph's outputs are a pure function of the weathergen binary, the graph and its
textures, so every action here is safe for --disk_cache, --remote_cache and remote
execution (docs/scaling.md).
"""

# Files `weathergen compile` writes per target, after "NAME." (cli/compile_command.cpp).
_TARGET_SUFFIXES = {
    "glsl": ["vert.glsl", "frag.glsl"],
    "hlsl": ["vert.hlsl", "frag.hlsl"],
    "spirv": [
        lang + "." + stage + ext
        for lang in ["glsl", "hlsl"]
        for stage in ["vert", "frag"]
        for ext in [".spv", ".spvasm"]
    ],
    "msl": ["vert.msl", "frag.msl"],
    "glsles": ["vert.es.glsl", "frag.es.glsl"],
}

def _material_name(graph):
    # weathergen names outputs after the graph's "name"; the rule cannot read JSON at
    # analysis time, so it requires that name to be the file's stem.
    return graph.basename[:-len(".json")] if graph.basename.endswith(".json") else graph.basename

def _weathergen_materials_impl(ctx):
    for target in ctx.attr.targets:
        if target not in _TARGET_SUFFIXES:
            fail("unknown target '%s' (use %s)" % (target, ", ".join(_TARGET_SUFFIXES.keys())))
    suffixes = ["reflect.json"]
    for target in ctx.attr.targets:
        suffixes += _TARGET_SUFFIXES[target]
    if ctx.attr.emit_header:
        suffixes.append("hpp")

    all_outputs = []
    seen = {}
    for graph in ctx.files.graphs:
        name = _material_name(graph)
        if name in seen:
            fail("two graphs name material '%s': %s and %s" % (name, seen[name], graph.path))
        seen[name] = graph.path
        outputs = [ctx.actions.declare_file("%s/%s.%s" % (ctx.label.name, name, s)) for s in suffixes]

        # "compile" starts the persistent worker; the rest is each request's arguments,
        # in a parameter file as workers need (weathergen reads it with --flagfile when
        # the action runs as a plain process).
        command = ctx.actions.args()
        command.add("compile")
        args = ctx.actions.args()
        args.use_param_file("--flagfile=%s", use_always = True)
        args.set_param_file_format("multiline")
        args.add(graph)
        args.add("-o", outputs[0].dirname)
        args.add("--target", ",".join(ctx.attr.targets))
        args.add("-j", "1")
        args.add("-q")
        args.add("--no-cache")  # Bazel's own caches hold the outputs
        if ctx.attr.optimize:
            args.add("-O")
        if ctx.attr.emit_header:
            args.add("--emit-header")

        # Every texture and library is an input of every graph: file paths are relative
        # to the graph and only known to weathergen, so the sandbox must hold them all.
        ctx.actions.run(
            executable = ctx.executable.compiler,
            arguments = [command, args],
            inputs = [graph] + ctx.files.textures + ctx.files.libraries,
            outputs = outputs,
            mnemonic = "WeathergenCompile",
            # One process compiles many materials: glslang's start-up is paid once.
            execution_requirements = {
                "supports-workers": "1",
                "requires-worker-protocol": "json",
            },
            progress_message = "Compiling material %s" % name,
        )
        all_outputs += outputs

    return [DefaultInfo(files = depset(all_outputs))]

weathergen_materials = rule(
    implementation = _weathergen_materials_impl,
    doc = "Compiles material graphs to shaders, SPIR-V and NAME.reflect.json under <name>/.",
    attrs = {
        "graphs": attr.label_list(
            allow_files = [".json"],
            mandatory = True,
            doc = "Material graphs; each file's stem must equal its \"name\".",
        ),
        "textures": attr.label_list(
            allow_files = True,
            doc = "Image files the graphs reference, at their paths relative to the graphs.",
        ),
        "libraries": attr.label_list(
            allow_files = [".json"],
            doc = "Graph libraries the graphs include, at their paths relative to the graphs.",
        ),
        "targets": attr.string_list(
            default = ["glsl", "hlsl", "spirv"],
            doc = "Any of glsl, hlsl, spirv, msl, glsles.",
        ),
        "optimize": attr.bool(default = False, doc = "Pass -O (spirv-opt performance passes)."),
        "emit_header": attr.bool(default = False, doc = "Also write NAME.hpp (std140 C++ structs)."),
        "compiler": attr.label(
            default = "//tools:weathergen",
            allow_single_file = True,
            executable = True,
            cfg = "exec",
            doc = "The weathergen binary.",
        ),
    },
)
