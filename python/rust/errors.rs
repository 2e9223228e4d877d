//! Python exceptions: the classes live in `exact2d/_errors.py` (so that they can inherit from
//! two built-in classes, such as `ValueError`); Rust looks them up by name and raises them
//! with the Rust message.

use pyo3::prelude::*;
use pyo3::types::PyType;

/// The names of the exception classes in `exact2d._errors`.
#[derive(Clone, Copy, Debug)]
pub enum Class {
    /// `InvalidInputError` (a `ValueError`): a number out of range, a bad shape.
    InvalidInput,
    /// `OverlapError` (an `InvalidInputError`): a new body would overlap another.
    Overlap,
    /// `UnknownHandleError` (an `InvalidInputError` and a `LookupError`).
    UnknownHandle,
    /// `TimeBeforeNowError` (an `InvalidInputError`).
    TimeBeforeNow,
    /// `SceneError` (an `InvalidInputError`): a scene the format refuses.
    Scene,
    /// `StalledError` (a `RuntimeError`): the engine's safety net.
    Stalled,
    /// `InvalidAimError` (a `GameError` and a `ValueError`).
    InvalidAim,
    /// `InvalidConfigError` (a `GameError` and a `ValueError`).
    InvalidConfig,
    /// `WrongPhaseError` (a `GameError` and a `RuntimeError`).
    WrongPhase,
    /// `SaveError` (a `GameError` and a `ValueError`): a save file that cannot be read.
    Save,
    /// `GameError`: any other refusal of the game.
    Game,
}

impl Class {
    fn name(self) -> &'static str {
        match self {
            Class::InvalidInput => "InvalidInputError",
            Class::Overlap => "OverlapError",
            Class::UnknownHandle => "UnknownHandleError",
            Class::TimeBeforeNow => "TimeBeforeNowError",
            Class::Scene => "SceneError",
            Class::Stalled => "StalledError",
            Class::InvalidAim => "InvalidAimError",
            Class::InvalidConfig => "InvalidConfigError",
            Class::WrongPhase => "WrongPhaseError",
            Class::Save => "SaveError",
            Class::Game => "GameError",
        }
    }
}

impl Class {
    const ALL: [Class; 11] = [
        Class::InvalidInput,
        Class::Overlap,
        Class::UnknownHandle,
        Class::TimeBeforeNow,
        Class::Scene,
        Class::Stalled,
        Class::InvalidAim,
        Class::InvalidConfig,
        Class::WrongPhase,
        Class::Save,
        Class::Game,
    ];

    /// The class of an exception raised by this module (to raise it again with a prefix);
    /// `InvalidInput` for any other.
    pub fn from_err(py: Python<'_>, err: &PyErr) -> Class {
        let name = err
            .get_type(py)
            .name()
            .map(|n| n.to_string())
            .unwrap_or_default();
        Class::ALL
            .into_iter()
            .find(|c| c.name() == name)
            .unwrap_or(Class::InvalidInput)
    }
}

/// An exception of `class` carrying `message`.
pub fn error(class: Class, message: impl Into<String>) -> PyErr {
    let message = message.into();
    Python::with_gil(|py| {
        let found = py
            .import("exact2d._errors")
            .and_then(|module| module.getattr(class.name()))
            .and_then(|cls| cls.downcast_into::<PyType>().map_err(PyErr::from));
        match found {
            Ok(cls) => PyErr::from_type(cls, message),
            Err(e) => e,
        }
    })
}

/// An `InvalidInputError` carrying `message`.
pub fn invalid(message: impl Into<String>) -> PyErr {
    error(Class::InvalidInput, message)
}
