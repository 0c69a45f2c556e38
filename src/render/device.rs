//! The wgpu adapter, device and queue, and render pipelines built from translated WGSL.
//!
//! The adapter is chosen deterministically: Vulkan adapters sorted by kind (discrete,
//! integrated, virtual, CPU) and then by name; `EFFECTC_ADAPTER=<substring>` picks one by
//! name. Pipeline creation errors surface through an error scope and are returned as text.

use crate::back::reflect::Reflection;

/// A device ready to build pipelines and render.
pub struct Gpu {
    pub adapter: wgpu::Adapter,
    pub info: wgpu::AdapterInfo,
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    /// Errors raised outside an error scope (wgpu's default would panic); see [`Gpu::take_error`].
    uncaptured: std::sync::Arc<std::sync::Mutex<Vec<String>>>,
}

/// Why no device could be created.
#[derive(Debug, Clone, PartialEq)]
pub struct NoGpu(pub String);

impl std::fmt::Display for NoGpu {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

fn kind_rank(t: wgpu::DeviceType) -> u8 {
    match t {
        wgpu::DeviceType::DiscreteGpu => 0,
        wgpu::DeviceType::IntegratedGpu => 1,
        wgpu::DeviceType::VirtualGpu => 2,
        wgpu::DeviceType::Cpu => 3,
        wgpu::DeviceType::Other => 4,
    }
}

impl Gpu {
    /// How long a frame may take when the user does not say: 5 s on a GPU, 30 s on a
    /// software rasterizer (lavapipe, WARP), where a correct heavy frame takes seconds.
    pub fn default_frame_timeout(&self) -> std::time::Duration {
        std::time::Duration::from_secs(if self.info.device_type == wgpu::DeviceType::Cpu { 30 } else { 5 })
    }

    /// Opens the chosen Vulkan adapter.
    pub fn new() -> Result<Gpu, NoGpu> {
        // Mesa's Vulkan loader complains on stderr when this is unset (headless machines,
        // CI); the directory is not used for offscreen rendering.
        if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
            std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
        }
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
            backends: wgpu::Backends::VULKAN,
            ..wgpu::InstanceDescriptor::new_without_display_handle()
        });
        let mut adapters = pollster::block_on(instance.enumerate_adapters(wgpu::Backends::VULKAN));
        adapters.sort_by_key(|a| {
            let i = a.get_info();
            (kind_rank(i.device_type), i.name.clone())
        });
        let wanted = std::env::var("EFFECTC_ADAPTER").ok();
        let adapter = adapters.into_iter().find(|a| wanted.as_deref().is_none_or(|w| a.get_info().name.contains(w))).ok_or_else(|| {
            NoGpu(match wanted {
                Some(w) => format!("no Vulkan adapter's name contains `{w}` (EFFECTC_ADAPTER)"),
                None => "no Vulkan adapter found; on Debian/Ubuntu install Mesa's CPU driver: \
                             `apt-get install mesa-vulkan-drivers libvulkan1` (or run ./setup.sh)"
                    .to_string(),
            })
        })?;
        let info = adapter.get_info();
        // Timestamps time frames on the GPU when the adapter has them (lavapipe does).
        // Blending into Rgba32Float (`--float`) where the adapter can.
        // FLOAT32_FILTERABLE: a multi-pass effect samples its rgba32f targets (and every float
        // target under --float) through filtering samplers, as GL does.
        // VERTEX_WRITABLE_STORAGE: `effectc stress` counts non-finite values of the vertex
        // stage in a storage buffer.
        // PRIMITIVE_INDEX, DUAL_SOURCE_BLENDING, SHADER_F16: a fragment stage reading
        // `gl_PrimitiveID`, writing a second-source output (`layout(index = 1)`), or a stage
        // computing with 16-bit floats (N0109).
        // TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES: an image of a format WebGPU's core lists
        // no storage for (`r16f`, `rgb10_a2`; GL and Vulkan store to them) where the
        // adapter can.
        let wanted = wgpu::Features::TIMESTAMP_QUERY
            | wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES
            | wgpu::Features::PRIMITIVE_INDEX
            | wgpu::Features::DUAL_SOURCE_BLENDING
            | wgpu::Features::SHADER_F16
            | wgpu::Features::FLOAT32_BLENDABLE
            | wgpu::Features::FLOAT32_FILTERABLE
            | wgpu::Features::VERTEX_WRITABLE_STORAGE;
        let features = adapter.features() & wanted;
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("effectc"),
            required_features: features,
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .map_err(|e| NoGpu(format!("the adapter `{}` refused a device: {e}", info.name)))?;
        let uncaptured = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
        let sink = uncaptured.clone();
        device.on_uncaptured_error(std::sync::Arc::new(move |e: wgpu::Error| {
            if let Ok(mut errors) = sink.lock() {
                errors.push(e.to_string());
            }
        }));
        Ok(Gpu { adapter, info, device, queue, uncaptured })
    }

    /// The first error wgpu raised outside an error scope since the last call, if any.
    pub fn take_error(&self) -> Option<String> {
        let mut errors = self.uncaptured.lock().ok()?;
        let first = errors.first().cloned();
        errors.clear();
        first
    }

    /// Whether vertex shaders may write storage buffers on this device.
    pub fn vertex_storage(&self) -> bool {
        self.device.features().contains(wgpu::Features::VERTEX_WRITABLE_STORAGE)
    }

    /// Whether colour targets of `format` can blend on this device.
    pub fn can_blend(&self, format: wgpu::TextureFormat) -> bool {
        match format.sample_type(None, None) {
            Some(wgpu::TextureSampleType::Float { filterable: true }) => true,
            Some(wgpu::TextureSampleType::Float { filterable: false }) => {
                self.device.features().contains(wgpu::Features::FLOAT32_BLENDABLE)
            }
            _ => false,
        }
    }

    /// One line naming the adapter, for `--verbose`.
    pub fn describe(&self) -> String {
        format!(
            "{} ({:?}, {:?}, driver {} {})",
            self.info.name, self.info.device_type, self.info.backend, self.info.driver, self.info.driver_info
        )
    }

    /// Builds a render pipeline from translated WGSL with one interleaved vertex buffer
    /// holding every vertex input (formats from the reflection) and one colour target per
    /// fragment output (Rgba8Unorm, or 32-bit integer formats for integer outputs).
    pub fn build_pipeline(&self, wgsl: &str, reflection: &Reflection) -> Result<wgpu::RenderPipeline, String> {
        use crate::render::attributes::{input_format, packed_layout};
        // A folded geometry program pulls its vertices from storage buffers.
        let pulled = reflection.geometry.is_some();
        let (attributes, stride) =
            packed_layout(reflection.vertex_inputs.iter().filter(|_| !pulled).map(|v| (v.location, input_format(v))));
        let spec = PipelineSpec {
            label: &reflection.effect,
            wgsl,
            vertex_stride: stride,
            attributes: &attributes,
            instance_stride: 0,
            instance_attributes: &[],
            colors: color_formats(reflection, wgpu::TextureFormat::Rgba8Unorm),
            blend: None,
            depth: None,
            depth_write: true,
            depth_compare: wgpu::CompareFunction::Less,
            cull: None,
            front_face: wgpu::FrontFace::Ccw,
            fragment: reflection.entry_points.iter().any(|e| e.name == "fs_main"),
            topology: topology(reflection),
            layout: None,
        };
        self.pipeline(&spec)
    }

    /// Builds a render pipeline; wgpu's validation errors come back as text.
    pub fn pipeline(&self, spec: &PipelineSpec<'_>) -> Result<wgpu::RenderPipeline, String> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = self.device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(spec.label),
            source: wgpu::ShaderSource::Wgsl(spec.wgsl.into()),
        });
        let mut buffers = Vec::new();
        if !spec.attributes.is_empty() {
            buffers.push(Some(wgpu::VertexBufferLayout {
                array_stride: spec.vertex_stride,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: spec.attributes,
            }));
        }
        if !spec.instance_attributes.is_empty() {
            buffers.push(Some(wgpu::VertexBufferLayout {
                array_stride: spec.instance_stride,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: spec.instance_attributes,
            }));
        }
        let targets: Vec<Option<wgpu::ColorTargetState>> = spec
            .colors
            .iter()
            .map(|f| {
                f.map(|format| wgpu::ColorTargetState {
                    format,
                    // Integer targets cannot blend; 32-bit float ones only with FLOAT32_BLENDABLE.
                    blend: spec.blend.filter(|_| self.can_blend(format)),
                    write_mask: wgpu::ColorWrites::ALL,
                })
            })
            .collect();
        // wgpu compiles the WGSL with naga's SPIR-V writer, which can panic on a module its
        // WGSL reader accepted: contained here as an error, not a crash of the run.
        let made = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            self.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(spec.label),
                layout: spec.layout,
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_main"),
                    compilation_options: Default::default(),
                    buffers: &buffers,
                },
                primitive: wgpu::PrimitiveState {
                    topology: spec.topology,
                    cull_mode: spec.cull,
                    front_face: spec.front_face,
                    ..Default::default()
                },
                depth_stencil: spec.depth.map(|format| wgpu::DepthStencilState {
                    format,
                    depth_write_enabled: Some(spec.depth_write),
                    depth_compare: Some(spec.depth_compare),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: wgpu::MultisampleState::default(),
                fragment: spec.fragment.then(|| wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs_main"),
                    compilation_options: Default::default(),
                    targets: &targets,
                }),
                multiview_mask: None,
                cache: None,
            })
        }));
        contained(made, pollster::block_on(scope.pop()))
    }

    /// Builds the compute pipeline of `wgsl`'s `cs_main`; wgpu's validation errors come
    /// back as text.
    pub fn compute_pipeline(&self, label: &str, wgsl: &str) -> Result<wgpu::ComputePipeline, String> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = self
            .device
            .create_shader_module(wgpu::ShaderModuleDescriptor { label: Some(label), source: wgpu::ShaderSource::Wgsl(wgsl.into()) });
        let made = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            self.device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(label),
                layout: None,
                module: &module,
                entry_point: Some("cs_main"),
                compilation_options: Default::default(),
                cache: None,
            })
        }));
        contained(made, pollster::block_on(scope.pop()))
    }
}

/// A pipeline wgpu made, or why not: its shader compiler (naga's SPIR-V writer) panicked,
/// contained as an error, or its validation failed.
fn contained<T>(made: std::thread::Result<T>, validation: Option<wgpu::Error>) -> Result<T, String> {
    let pipeline = made.map_err(|payload| {
        format!(
            "wgpu's shader compiler (naga's SPIR-V writer) crashed on the translated WGSL: {}",
            crate::front::naga_run::panic_message(payload.as_ref())
        )
    })?;
    match validation {
        Some(e) => Err(e.to_string()),
        None => Ok(pipeline),
    }
}

/// What a render pipeline is built from.
pub struct PipelineSpec<'a> {
    pub label: &'a str,
    pub wgsl: &'a str,
    /// One interleaved per-vertex buffer (slot 0); no buffer when `attributes` is empty.
    pub vertex_stride: u64,
    pub attributes: &'a [wgpu::VertexAttribute],
    /// One interleaved per-instance buffer (the next slot); none when empty.
    pub instance_stride: u64,
    pub instance_attributes: &'a [wgpu::VertexAttribute],
    /// Colour target formats by location (`None` for a gap).
    pub colors: Vec<Option<wgpu::TextureFormat>>,
    /// Blending of colour targets that can blend.
    pub blend: Option<wgpu::BlendState>,
    /// Depth buffer format (depth test `less`).
    pub depth: Option<wgpu::TextureFormat>,
    pub depth_write: bool,
    /// The depth test (`glDepthFunc`).
    pub depth_compare: wgpu::CompareFunction,
    pub cull: Option<wgpu::Face>,
    /// Counter-clockwise as in GL; clockwise when the translation flipped clip y.
    pub front_face: wgpu::FrontFace,
    /// The module has `fs_main`.
    pub fragment: bool,
    /// Triangle lists, except for a folded geometry stage that emits lines or points.
    pub topology: wgpu::PrimitiveTopology,
    /// An explicit pipeline layout; `None` derives it from the shader.
    pub layout: Option<&'a wgpu::PipelineLayout>,
}

/// The pipeline topology: a triangle list, or for a folded geometry stage the list its
/// output strips became.
pub fn topology(r: &Reflection) -> wgpu::PrimitiveTopology {
    match r.geometry.as_ref().map(|g| g.topology) {
        Some("point-list") => wgpu::PrimitiveTopology::PointList,
        Some("line-list") => wgpu::PrimitiveTopology::LineList,
        _ => wgpu::PrimitiveTopology::TriangleList,
    }
}

/// Colour target formats by fragment output location: `float` for floating-point outputs,
/// 32-bit integer formats for integer outputs.
pub fn color_formats(reflection: &Reflection, float: wgpu::TextureFormat) -> Vec<Option<wgpu::TextureFormat>> {
    let mut targets = Vec::new();
    for o in &reflection.fragment_outputs {
        while targets.len() < o.location as usize {
            targets.push(None);
        }
        targets.push(Some(if o.wgsl_type.contains("i32") {
            wgpu::TextureFormat::Rgba32Sint
        } else if o.wgsl_type.contains("u32") {
            wgpu::TextureFormat::Rgba32Uint
        } else {
            float
        }));
    }
    targets
}
