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
    /// Opens the chosen Vulkan adapter.
    pub fn new() -> Result<Gpu, NoGpu> {
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
        let adapter = adapters
            .into_iter()
            .find(|a| wanted.as_deref().is_none_or(|w| a.get_info().name.contains(w)))
            .ok_or_else(|| {
                NoGpu(match wanted {
                    Some(w) => format!("no Vulkan adapter's name contains `{w}` (EFFECTC_ADAPTER)"),
                    None => "no Vulkan adapter found; on Debian/Ubuntu install Mesa's CPU driver: \
                             `apt-get install mesa-vulkan-drivers libvulkan1` (or run ./setup.sh)"
                        .to_string(),
                })
            })?;
        let info = adapter.get_info();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("effectc"),
            required_features: wgpu::Features::empty(),
            required_limits: wgpu::Limits::downlevel_defaults().using_resolution(adapter.limits()),
            ..Default::default()
        }))
        .map_err(|e| NoGpu(format!("the adapter `{}` refused a device: {e}", info.name)))?;
        Ok(Gpu { adapter, info, device, queue })
    }

    /// One line naming the adapter, for `--verbose`.
    pub fn describe(&self) -> String {
        format!("{} ({:?}, {:?}, driver {} {})", self.info.name, self.info.device_type, self.info.backend, self.info.driver, self.info.driver_info)
    }

    /// Builds a render pipeline from translated WGSL: one vertex buffer per vertex input
    /// (format from the reflection), one colour target per fragment output.
    pub fn build_pipeline(&self, wgsl: &str, reflection: &Reflection) -> Result<wgpu::RenderPipeline, String> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = self.device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(&reflection.effect),
            source: wgpu::ShaderSource::Wgsl(wgsl.into()),
        });
        let attributes: Vec<[wgpu::VertexAttribute; 1]> = reflection
            .vertex_inputs
            .iter()
            .map(|v| {
                [wgpu::VertexAttribute {
                    format: vertex_format(v.format.as_deref().unwrap_or("float32x4")),
                    offset: 0,
                    shader_location: v.location,
                }]
            })
            .collect();
        let buffers: Vec<Option<wgpu::VertexBufferLayout>> = attributes
            .iter()
            .map(|a| {
                Some(wgpu::VertexBufferLayout {
                    array_stride: a[0].format.size(),
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: a,
                })
            })
            .collect();
        let mut targets: Vec<Option<wgpu::ColorTargetState>> = Vec::new();
        for o in &reflection.fragment_outputs {
            while targets.len() < o.location as usize {
                targets.push(None);
            }
            let format = if o.wgsl_type.contains("i32") {
                wgpu::TextureFormat::Rgba32Sint
            } else if o.wgsl_type.contains("u32") {
                wgpu::TextureFormat::Rgba32Uint
            } else {
                wgpu::TextureFormat::Rgba8Unorm
            };
            targets.push(Some(format.into()));
        }
        let has = |name: &str| reflection.entry_points.iter().any(|e| e.name == name);
        if !has("vs_main") {
            return Err("the module has no vertex entry point".into());
        }
        let pipeline = self.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(&reflection.effect),
            layout: None,
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &buffers,
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            fragment: has("fs_main").then(|| wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_main"),
                compilation_options: Default::default(),
                targets: &targets,
            }),
            multiview_mask: None,
            cache: None,
        });
        match pollster::block_on(scope.pop()) {
            Some(e) => Err(e.to_string()),
            None => Ok(pipeline),
        }
    }
}

/// wgpu's vertex format for a reflection format name (`float32x3`).
pub fn vertex_format(name: &str) -> wgpu::VertexFormat {
    use wgpu::VertexFormat as F;
    match name {
        "float32" => F::Float32,
        "float32x2" => F::Float32x2,
        "float32x3" => F::Float32x3,
        "sint32" => F::Sint32,
        "sint32x2" => F::Sint32x2,
        "sint32x3" => F::Sint32x3,
        "sint32x4" => F::Sint32x4,
        "uint32" => F::Uint32,
        "uint32x2" => F::Uint32x2,
        "uint32x3" => F::Uint32x3,
        "uint32x4" => F::Uint32x4,
        "float64" => F::Float64,
        "float64x2" => F::Float64x2,
        "float64x3" => F::Float64x3,
        "float64x4" => F::Float64x4,
        _ => F::Float32x4,
    }
}
