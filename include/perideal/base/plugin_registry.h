// ---------------------------------------------------------------------
// PeriDeal: a registry of named plugins, in the manner of ASPECT.
// ---------------------------------------------------------------------
#ifndef perideal_base_plugin_registry_h
#define perideal_base_plugin_registry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace perideal
{
  /**
   * @brief A registry of the plugins that implement one interface.
   *
   * Every plugin registers itself (see PERIDEAL_REGISTER_PLUGIN) with a name, a description, a
   * function that declares its own parameter subsection and a factory. The names allowed in a
   * parameter file come from here, so a new plugin needs no change elsewhere. Libraries are
   * SHARED so that the static registration objects survive linking.
   */
  template <typename InterfaceType>
  class PluginRegistry
  {
  public:
    /// Creates a plugin.
    using Factory = std::function<std::unique_ptr<InterfaceType>()>;
    /// Declares a plugin's entries in the current subsection of a ParameterHandler.
    using ParameterDeclarer = std::function<void(dealii::ParameterHandler &)>;

    /// What a plugin registers besides its name.
    struct Entry
    {
      /// Its description (listed in the documentation of the entry that chooses it), the
      /// declaration of its subsection and its factory.
      ///@{
      std::string       description;
      ParameterDeclarer declare_parameters;
      Factory           factory;
      ///@}
    };

    /**
     * @brief Register a plugin; called by the registration macro at library load time.
     */
    static bool
    register_plugin(const std::string       &name,
                    const std::string       &description,
                    const ParameterDeclarer &declare_parameters,
                    const Factory           &factory)
    {
      entries()[name] = Entry{description, declare_parameters, factory};
      return true;
    }

    /**
     * @brief The names of all registered plugins separated by '|', for Patterns::Selection.
     */
    static std::string
    pattern_string()
    {
      std::string result;
      for (const auto &entry : entries())
        result += (result.empty() ? "" : "|") + entry.first;
      return result;
    }

    /**
     * @brief A documentation string listing every plugin with its description.
     */
    static std::string
    documentation()
    {
      std::string result;
      for (const auto &entry : entries())
        result += "'" + entry.first + "': " + entry.second.description + " ";
      return result;
    }

    /**
     * @brief Declare the subsection of every plugin (named after the plugin).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      for (const auto &entry : entries())
        if (entry.second.declare_parameters)
          {
            prm.enter_subsection(entry.first);
            entry.second.declare_parameters(prm);
            prm.leave_subsection();
          }
    }

    /**
     * @brief Create the plugin called @p name; @p entry names the parameter that chose it.
     */
    static std::unique_ptr<InterfaceType>
    create(const std::string &name, const std::string &entry)
    {
      const auto it = entries().find(name);
      AssertThrow(it != entries().end(),
                  dealii::ExcMessage("Unknown value <" + name + "> of the parameter <" + entry +
                                     ">. Accepted values: " + pattern_string() + "."));
      return it->second.factory();
    }

  private:
    static std::map<std::string, Entry> &
    entries()
    {
      static std::map<std::string, Entry> registered;
      return registered;
    }
  };
} // namespace perideal

#define PERIDEAL_REGISTRY_CONCAT_IMPL(a, b) a##b
#define PERIDEAL_REGISTRY_CONCAT(a, b) PERIDEAL_REGISTRY_CONCAT_IMPL(a, b)

/**
 * Register class @p classname (an implementation of @p interface) under @p name.
 */
#define PERIDEAL_REGISTER_PLUGIN(interface, classname, name, description)              \
  namespace                                                                            \
  {                                                                                    \
    const bool PERIDEAL_REGISTRY_CONCAT(perideal_registered_, __COUNTER__) =           \
      ::perideal::PluginRegistry<interface>::register_plugin(                          \
        name,                                                                          \
        description,                                                                   \
        [](dealii::ParameterHandler &prm) { classname::declare_parameters(prm); },     \
        []() -> std::unique_ptr<interface> { return std::make_unique<classname>(); }); \
  }

#endif
