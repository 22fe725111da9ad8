package rason.architecture;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.fields;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.domain.JavaField;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.lang.ArchCondition;
import com.tngtech.archunit.lang.ConditionEvents;
import com.tngtech.archunit.lang.SimpleConditionEvent;

/**
 * The shape of jason_lib: a leaf package of shared words and values ({@code rason.core})
 * that depends on nothing of ours; the concerns (actions, perception, fleet, mind) that
 * depend on it and on no architecture, infrastructure or composition root; the agent
 * architectures ({@code rason}) below the infrastructure ({@code rason.infra}) below the
 * composition root ({@code rason.bridge}); no package cycles; no process globals outside
 * the composition root; and (the thread rule's structural half) no Java interface
 * implemented in Python, so an agent's thread can never call into Python.
 */
class ArchitectureTest {

    static final String ROOT = "rason.bridge..";
    static final String INFRA = "rason.infra..";
    static final String[] CONCERNS = { "rason.action..", "rason.perception..", "rason.messaging..", "rason.mind.." };
    static final String CORE = "rason.core..";

    private static final JavaClasses CLASSES = new ClassFileImporter()
            .withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS).importPackages("rason");

    /** Classes of the package {@code rason} itself: the agent architectures and internal actions. */
    private static final DescribedPredicate<com.tngtech.archunit.core.domain.JavaClass> ARCHITECTURES =
            DescribedPredicate.describe("in package rason", c -> c.getPackageName().equals("rason"));

    @Test
    void noPackageCycles() {
        slices().matching("rason.(**)").should().beFreeOfCycles().check(CLASSES);
    }

    @Test
    void theCoreDependsOnNothingOfOurs() {
        noClasses().that().resideInAPackage(CORE).should().dependOnClassesThat(ARCHITECTURES.or(
                com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAnyPackage(concat(CONCERNS, INFRA, ROOT))))
                .check(CLASSES);
    }

    @Test
    void theConcernsKnowNoArchitectureInfrastructureOrRoot() {
        noClasses().that().resideInAnyPackage(CONCERNS).should().dependOnClassesThat(ARCHITECTURES.or(
                com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAnyPackage(INFRA, ROOT))).check(CLASSES);
    }

    /** The MQTT fleet channel is an adapter of the fleet port: it knows the core and messaging only. */
    @Test
    void theMqttChannelKnowsOnlyTheCoreAndMessaging() {
        noClasses().that().resideInAPackage("rason.messaging.mqtt..").should().dependOnClassesThat(ARCHITECTURES.or(
                com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAnyPackage("rason.action..",
                        "rason.perception..", "rason.mind..", INFRA, ROOT))).check(CLASSES);
        noClasses().that().resideInAPackage("rason.messaging").should().dependOnClassesThat()
                .resideInAPackage("rason.messaging.mqtt..").check(CLASSES);
    }

    @Test
    void theArchitecturesKnowNoInfrastructureOrRoot() {
        noClasses().that(ARCHITECTURES).should().dependOnClassesThat().resideInAnyPackage(INFRA, ROOT).check(CLASSES);
    }

    @Test
    void theInfrastructureKnowsNoRoot() {
        noClasses().that().resideInAPackage(INFRA).should().dependOnClassesThat().resideInAPackage(ROOT)
                .check(CLASSES);
    }

    /** Mutable or shared state in a static field is a process global: only the composition root may hold one. */
    @Test
    void noGlobalsOutsideTheCompositionRoot() {
        fields().that().areStatic().and().areDeclaredInClassesThat().resideOutsideOfPackage(ROOT)
                .should(beConstants()).check(CLASSES);
    }

    /** Jason's own process-wide look-ups are for the infrastructure and the composition root only. */
    @Test
    void jasonsGlobalsAreReadByTheInfrastructureOnly() {
        noClasses().that().resideOutsideOfPackages(INFRA, ROOT).should().callMethod(
                jason.infra.local.BaseLocalMAS.class, "getRunner").orShould().callMethod(
                        jason.runtime.RuntimeServicesFactory.class, "get")
                .check(CLASSES);
    }

    /** Durations are measured on an injected clock, so tests move time instead of sleeping. */
    @Test
    void theWallClockIsReadThroughClockOnly() {
        noClasses().that().resideOutsideOfPackage(CORE).should().callMethod(System.class, "nanoTime")
                .orShould().callMethod(System.class, "currentTimeMillis").check(CLASSES);
    }

    private static final Pattern PYTHON_IMPLEMENTS_JAVA = Pattern.compile("\\bJProxy\\b|@JImplements|\\bJImplements\\b");

    /**
     * Python never implements a Java interface (JPype's JProxy or @JImplements): Java then
     * holds no Python callable, and no agent thread can call into Python.
     */
    @Test
    void noJavaInterfaceIsImplementedInPython() throws IOException {
        Path src = Path.of("..", "src");
        List<String> offenders;
        try (Stream<Path> files = Files.walk(src)) {
            offenders = files.filter(p -> p.toString().endsWith(".py")).filter(ArchitectureTest::implementsJava)
                    .map(Path::toString).sorted().toList();
        }
        assertEquals(List.of(), offenders, "Python sources that implement a Java interface");
    }

    static boolean implementsJava(Path file) {
        try {
            return PYTHON_IMPLEMENTS_JAVA.matcher(Files.readString(file)).find();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    // A ThreadLocal holds per-thread scratch (a Mac), never a value one thread hands another.
    private static final Set<String> CONSTANT_TYPES = Set.of("java.lang.String", "java.util.logging.Logger",
            "java.util.regex.Pattern", "rason.core.Clock", "jason.asSyntax.Atom", "java.lang.ThreadLocal");

    /**
     * final, and of a type whose value cannot change: primitives, strings, loggers, patterns,
     * enums, records, Jason atoms, a stateless clock (and the compiler's own switch tables).
     */
    static ArchCondition<JavaField> beConstants() {
        return new ArchCondition<>("be constants") {
            @Override
            public void check(JavaField f, ConditionEvents events) {
                boolean finalField = f.getModifiers().contains(com.tngtech.archunit.core.domain.JavaModifier.FINAL);
                var type = f.getRawType();
                boolean constantType = type.isPrimitive() || type.isEnum() || type.isRecord()
                        || CONSTANT_TYPES.contains(type.getName()) || f.getName().equals("serialVersionUID")
                        || f.getName().equals("$VALUES") || f.getName().startsWith("$SwitchMap$")
                        || (type.isArray() && type.getComponentType().getName().equals("java.lang.String")
                                && f.getName().equals("NONE"));
                if (!finalField || !constantType)
                    events.add(SimpleConditionEvent.violated(f, f.getFullName() + " is a process global ("
                            + (finalField ? "of type " + type.getName() : "not final") + ")"));
            }
        };
    }

    private static String[] concat(String[] a, String... b) {
        return Stream.concat(Stream.of(a), Stream.of(b)).toArray(String[]::new);
    }
}
